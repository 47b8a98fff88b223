// What MinDepth did to the depths of a set of points (a Bathymetry depth field read at
// the mesh nodes): plain data that the mesh statistics carry to the summary and --stats.
#pragma once

#include <cstdint>

namespace sm::field {

/// How many points MinDepth raised (`dry`: of them, those the grid puts on land, depth
/// <= 0), and the point it raised most (ties: the first),
/// with the grid's depth there (bilinear, or the cells' mean) and the depth given
/// instead.
struct DepthClampReport {
  double min_depth = 0;
  std::uint64_t points = 0, clamped = 0, dry = 0;
  bool has_worst = false;
  double lon = 0, lat = 0, grid_depth = 0, value = 0;
};

}  // namespace sm::field
