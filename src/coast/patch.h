// A local shoreline source replacing the base one inside a lon/lat box (what OceanMesh2D
// does with several shorelines by priority): land = (base land outside the box) U (local
// land inside it). The base rings are clipped to the outside of the box, the local rings
// to its inside, and the cut chains are linked along the box (perimeter_link.h): where the
// two sources disagree at the box edge, the stretch of box between the two crossings
// closes the gap, and the largest such step is reported.
#pragma once

#include <cstddef>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

struct PatchReport {
  std::size_t steps = 0;          // stretches of box edge in the result (where the sources disagree)
  double max_step_m = 0;          // the longest of them, metres on the sphere of radius_m
  geo::LonLat max_step_at{};      // its middle
  std::size_t base_chains = 0, local_chains = 0, local_inside = 0;
};

/// `base` and `local` cleaned and oriented land on the left (orient_rings); only land
/// levels are spliced (water levels of the base are kept outside the box and dropped
/// inside or across it). The box must lie within [-180, 180] of the data's longitudes
/// (no 360-degree shifts: a patch is local). Errors (option "Patch"/"PatchBox"): a box
/// without west < east and south < north, a local source with no shoreline inside the
/// box, an open local polyline, orientations that disagree along the box.
Result<std::vector<Ring>> splice_patch(const std::vector<Ring>& base, const std::vector<Ring>& local,
                                       const LonLatBox& box, double radius_m, PatchReport* report = nullptr);

}  // namespace sm::coast
