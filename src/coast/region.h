// Region clipping of shorelines to a lon/lat box on the sphere: coastlines are cut at the
// box, and the cut coastlines are closed along the box boundary by separate pieces
// flagged open_boundary (the open-sea boundary of a regional model).
#pragma once

#include <cstddef>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

/// One piece of a region loop: a coastline piece (land on its right, ocean on its left
/// once in the loop) or a piece of the box boundary.
struct RegionPiece {
  std::vector<geo::LonLat> pts;
  bool open_boundary = false;
  std::size_t ring = static_cast<std::size_t>(-1);   // index of the input ring (coast pieces)
  /// Box pieces: indices into pts of the box corners they turn round. The samples get
  /// denser towards each corner (halving the step down to ~1 m), so that the import can
  /// keep a point close on each side and the B-spline through the kept points turns the
  /// corner within a small fraction of the accuracy instead of cutting it.
  std::vector<std::size_t> corners;
};

/// A closed loop bounding the ocean inside the box, ocean on the left (counter-clockwise
/// in lon/lat): the end of each piece is the start of the next.
struct RegionLoop {
  std::vector<RegionPiece> pieces;
};

struct RegionResult {
  std::vector<std::size_t> inside;   // input rings (closed) lying wholly inside the box
  std::vector<RegionLoop> loops;     // outer boundaries of the ocean in the box
};

struct RegionOptions {
  /// Largest step (degrees) between points put on the box boundary pieces; the
  /// coarsening then thins them with the accuracy field like any shoreline.
  double boundary_step_deg = 0.05;
  /// Smallest distance (degrees) of the graded samples next to a box corner.
  double corner_step_deg = 1e-5;
};

/// `rings` must be cleaned and oriented land-on-the-left (orient_rings). Edges of the
/// box are meridians and parallels, so they are straight in lon/lat; crossing points
/// interpolate linearly in lon/lat between two shoreline vertices (metres apart).
/// A ring may be shifted by 360 degrees to meet the box. Errors: an open polyline ending
/// strictly inside the box (it cannot be closed), inconsistent orientations along the
/// box, or a box lying wholly inside land.
Result<RegionResult> clip_to_region(const std::vector<Ring>& rings, const LonLatBox& box,
                                    const RegionOptions& opt = {});

/// Makes every closed ring counter-clockwise in lon/lat (land, or a lake's water, on
/// the left; decided with the exact orient2d at an extreme vertex) and every
/// pole-wrapping ring run so that its pole is on its left (westwards round the South
/// Pole). Returns the number of rings reversed.
std::size_t orient_rings(std::vector<Ring>& rings);

}  // namespace sm::coast
