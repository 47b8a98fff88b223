// The mean width 2A/P of a ring's water in metres, the narrow-water test of passage
// closing (passages.cpp: a new water loop narrower than the passage width is dropped). A
// deviation bound's closures cut the sea loop once each, and each cut asks the sea's mean
// width again: a pass over the ring per cut. The rope's sums (kept_rope.h) bound it in
// O(1), added in another order and without the mean point, so they only decide when the
// answer is certain beyond the two orders' rounding and the scale's range; otherwise, and
// whenever the width itself is wanted, the pass round the ring is made as before: the same
// doubles and the same decisions. The mean point (where the map's scale is read) is not summed: it
// lies within half the perimeter of any point of the ring and no farther from the origin
// than the farthest point made, which bounds the scale well enough for a ring far wider
// or narrower than the width (a sea after a cut, a sliver).
#pragma once

#include <optional>

#include "base/vec.h"
#include "coast/kept_rope.h"

namespace sm::coast {

/// Metres per (u,v) unit at uv on the sphere of `radius` (the stereographic map's scale).
inline double lambda_m(Vec2 uv, double radius) { return 2.0 * radius / (1.0 + norm2(uv)); }

/// Mean width 2|A|/P in metres of ring r, read round the ring in order (point i, then
/// segment i -> i + 1, the closing segment last): the reference value. 0 for no perimeter.
double ring_mean_width_m(const KeptRopes& ropes, KeptRopes::Rope r, double radius);

/// Bounds lo <= ring_mean_width_m <= hi from the rope's sums in O(1) (lo 0 and hi
/// infinite when the rounding leaves no useful bound: an area or perimeter lost in it).
struct MeanWidthBounds {
  double lo = 0;
  double hi = 0;
};
MeanWidthBounds bound_ring_mean_width_m(const KeptRopes& ropes, KeptRopes::Rope r, double radius);

/// Whether ring_mean_width_m(r) < width, when the estimate decides it for certain;
/// nullopt when the ring's pass must decide.
std::optional<bool> mean_width_surely_below(const KeptRopes& ropes, KeptRopes::Rope r, double radius, double width);

}  // namespace sm::coast
