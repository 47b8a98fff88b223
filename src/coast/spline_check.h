// Consistency of the cubic B-splines drawn through the control polygons (paper section
// 2.2: a B-spline stays in the convex hulls of its consecutive control points). A span of a
// uniform cubic B-spline lies in the convex hull of its 4 control points; where the hulls
// of two spans that share no control point overlap, the curves there may cross even though
// the control polygons do not (thin islands, narrow straits: shared/data/README.md).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/vec.h"

namespace sm::coast {

/// One loop for the check: its control points in order and whether the loop is one
/// periodic spline (else it is made of pieces, each a spline of its own).
struct SplineLoop {
  std::span<const Vec2> pts;            // first point not repeated
  std::span<const std::uint32_t> piece_start;   // for pieces: first control point of each piece
  bool periodic = true;
};

/// Two spans whose hulls overlap. A span is named by the control-polygon segment it
/// follows: segment s of loop l, from point s to point s+1.
struct HullOverlap {
  std::uint32_t loop_a, seg_a, loop_b, seg_b;
  Vec2 where;
};

/// All overlapping pairs of span hulls that share no control point, found through a grid
/// on the hulls' boxes; separation is decided exactly (orient2d, separating edges).
std::vector<HullOverlap> find_hull_overlaps(std::span<const SplineLoop> loops);

}  // namespace sm::coast
