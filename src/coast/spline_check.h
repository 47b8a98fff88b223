// Consistency of the cubic B-splines drawn through the control polygons (paper section
// 2.2: a B-spline stays in the convex hulls of its consecutive control points). A span of a
// uniform cubic B-spline lies in the convex hull of its 4 control points; where the hulls
// of two spans overlap, the curves there may cross even though the control polygons do not
// (thin islands, narrow straits). find_spline_crossings decides it:
// Bezier form of each span, de Casteljau halving while the hulls overlap.
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
  /// Per control point: the size (in the points' units) below which two pieces of curve
  /// whose hulls still overlap count as meeting (find_spline_crossings). Empty: 1e-7 of
  /// the loop's extent.
  std::span<const double> tol{};
  /// Per control point: whether the span following segment i (from point i to i+1) is
  /// tested. Empty: every span. A pair of two untested spans is taken as not meeting: the
  /// caller marks only the spans that changed since a check that found them apart.
  std::span<const char> active{};
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

/// Where the B-spline curves Gmsh draws through the loops (geo/curve_bspline.h: the uniform
/// cubic on a surface geometry; periodic loops wrap, pieces have their end points tripled)
/// cross, touch, or come closer than the tolerance: two spans (seg_a, seg_b as in
/// HullOverlap: the loop segment a span follows) or one span with itself (a loop in a
/// tight bend: seg_a == seg_b). Candidate pairs from a grid on the spans' boxes; each is
/// decided by halving both cubic Bezier spans (de Casteljau) while their control hulls
/// overlap (exact orient2d), down to the tolerance. Consecutive spans, which meet at their
/// joint, are separate when the directions from the joint to their control points span
/// disjoint angles. Only pairs with an active span (SplineLoop::active) are decided, so the
/// result is the full search's when no pair
/// of two inactive spans meets; only the spans that can meet an active one are made. Sorted,
/// each pair once (of two places found for one pair, the first in x then y). The pairs are
/// decided on up to `threads` threads (resolve_thread_count), the same result for any.
std::vector<HullOverlap> find_spline_crossings(std::span<const SplineLoop> loops, int threads = 1);

}  // namespace sm::coast
