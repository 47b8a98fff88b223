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
std::vector<SegmentHit> find_intersections(std::span<const std::vector<Vec2>> loops,
                                           IntersectionStats* stats = nullptr);

/// find_intersections on the pairs of which at least one segment is active (active[l][s],
/// one flag per segment): the repair's rounds change a few segments of a loop (a point put
/// back, a hit left for the next round), and a pair of two unchanged segments keeps its
/// verdict. Only the active segments are entered in a grid; each inactive one whose box
/// meets theirs looks in the cells it covers. The same records, sorted the same way, as
/// find_intersections restricted to those pairs, for every thread count (`threads`, as
/// parallel_for_chunks takes it).
std::vector<SegmentHit> find_intersections_at(std::span<const std::vector<Vec2>> loops,
                                              std::span<const std::vector<char>> active, int threads = 1);

/// Segments of different loops (or far apart in one loop) closer than `width(loop, seg)`
/// without touching: narrow straits. Found with the same grid, cells enlarged by the width.
struct NearMiss {
  std::uint32_t loop_a, seg_a, loop_b, seg_b;
  double distance;
  Vec2 where;
};
std::vector<NearMiss> find_near_misses(std::span<const std::vector<Vec2>> loops,
                                       std::span<const std::vector<double>> width);

/// The pairs find_near_misses tests (boxes padded by the widths meeting, distance below the
/// smaller width and not 0), of which at least one segment is active (active[l][s]), with
/// no pair of one loop left out for being near along it: a caller that keeps the pairs of
/// unchanged segments from one search to the next asks only about the segments that
/// changed, and decides about pairs on one loop with the loop as it is then. (loop_a,
/// seg_a) < (loop_b, seg_b); sorted as find_near_misses; `searched` (when given) is set to
/// the number of segments entered in the grid (the active ones). `threads`: the search's
/// (parallel_for_chunks); the result is the same for every count.
std::vector<NearMiss> find_near_pairs(std::span<const std::vector<Vec2>> loops,
                                      std::span<const std::vector<double>> width,
                                      std::span<const std::vector<char>> active, std::size_t* searched = nullptr,
                                      int threads = 1);

/// find_near_misses after the loops changed in places: `before` is find_near_misses of the
/// loops as they were, each place numbered as it is now (a loop renumbered or merged into
/// another: its records renumbered, in any order), and active[l][s] marks each segment
/// that is new or whose pairs may have changed (its geometry, width, or its distance along
/// its loop to the other segment of a pair); a place past its loop's end is gone. The records of two inactive segments
/// are those of `before` (the one-loop filter made again), the others are searched (find_near_pairs). The result is
/// find_near_misses(loops, width), record for record, at the cost of the active segments and the segments near them.
/// `threads`: the search's (find_near_pairs); the result is the same for every count.
std::vector<NearMiss> find_near_misses_again(std::span<const std::vector<Vec2>> loops,
                                             std::span<const std::vector<double>> width,
                                             std::span<const std::vector<char>> active, std::vector<NearMiss> before,
                                             int threads = 1);

/// Two loops joined across segment k_into of `into` and k_from of `from` (repair.cpp,
/// merge_across): into's polygon becomes its vertices from k_into + 1 round to k_into, then
/// from's from k_from + 1 round to k_from, the two segments replaced by the bridges
/// k_into -> k_from + 1 and k_from -> k_into + 1; from's polygon is emptied. n_into and
/// n_from: their vertex counts before.
struct LoopJoin {
  std::uint32_t into, from, k_into, k_from, n_into, n_from;
};

/// Renumbers the places of `near` for the joins (each loop in one join at most), and marks
/// in `active` (one flag per segment of the loops after the joins, cleared by the caller)
/// what find_near_misses_again must search again: the bridges and the two segments on each
/// side of each (a pair there may have been near along one loop, or become so). A `near`
/// sorted by place_pair_key stays sorted.
void renumber_for_joins(std::span<const LoopJoin> joins, std::vector<NearMiss>& near,
                        std::vector<std::vector<char>>& active);

}  // namespace sm::coast
