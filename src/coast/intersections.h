// Segment intersections within and between closed polygonal loops in the PolarSphere
// (u,v) plane, found through a uniform grid (no all-pairs test) and decided with the
// exact orient2d predicate.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/vec.h"

namespace sm::coast {

enum class HitKind : std::uint8_t {
  Cross,     // the two segments cross at one interior point
  Touch,     // an end point of one lies on the other (or they share a vertex illegally)
  Overlap,   // collinear and overlapping (includes a loop folding back on itself)
};

/// Segment s of loop l runs from vertex s to vertex (s+1) mod n.
struct SegmentHit {
  std::uint32_t loop_a, seg_a, loop_b, seg_b;   // (loop_a, seg_a) < (loop_b, seg_b)
  HitKind kind;
  Vec2 where;                                   // approximate location (for reports only)
};

struct IntersectionStats {
  std::size_t segments = 0, grid_cells = 0, candidate_pairs = 0;
};

/// Every pair of non-adjacent segments that cross, touch or overlap, plus adjacent ones
/// that fold back. Loops are closed (first point not repeated). Sorted, deterministic.
/// With `active` (one flag per loop), only pairs involving an active loop are tested: the
/// repair re-checks just the loops it changed.
std::vector<SegmentHit> find_intersections(std::span<const std::vector<Vec2>> loops,
                                           IntersectionStats* stats = nullptr, std::span<const char> active = {});

/// Segments of different loops (or far apart in one loop) closer than `width(loop, seg)`
/// without touching: narrow straits. Found with the same grid, cells enlarged by the width.
struct NearMiss {
  std::uint32_t loop_a, seg_a, loop_b, seg_b;
  double distance;
  Vec2 where;
};
std::vector<NearMiss> find_near_misses(std::span<const std::vector<Vec2>> loops,
                                       std::span<const std::vector<double>> width);

}  // namespace sm::coast
