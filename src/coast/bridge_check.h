// The check of a strait's bridge against the coast (repair.cpp, handle_straits): whether the
// bridge crosses a segment of the pass's polygons of a loop alive now. The polygons change
// only by the joins of the passes (LoopJoin, coast/intersections.h): a joined loop's
// polygon is its two loops' segments less the two the join replaced, plus its two bridges.
// So one grid of the first pass's segments serves every pass: each segment is told to the
// loop that holds it now (the loop its first loop was joined into), the replaced ones are
// struck out, and the bridges are in a small grid of their own. A grid of the joined
// loops' polygons made again each pass (continents that took in islands: most of the
// coast) was 0.65 s of the straits' 4.6 s at 3 km on the full GSHHG.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/vec.h"
#include "coast/intersections.h"
#include "coast/repair.h"
#include "coast/segment_grid.h"

namespace sm::coast {

class BridgeCheck {
 public:
  explicit BridgeCheck(std::size_t n_loops) : n_loops_(n_loops) {}
  /// The loops of join j change from the next pass on: called at that pass's start, before
  /// its polygons are joined (`polys` are still those of the pass that made the join).
  void merged(const LoopJoin& j, const std::vector<std::vector<Vec2>>& polys);
  /// A new pass: the bridges' grid is made again at its first question.
  void new_pass() { bridge_grid_.reset(); }
  /// Whether the bridge b0 -> b1 crosses a segment of the pass's polygons (polys) of a loop
  /// alive now, other than those sharing an end point with it (its neighbours in the new
  /// loop). The first call takes `polys` as the first pass's (every later pass's polygons
  /// must come from them by the joins told to merged()).
  bool crosses(const std::vector<WorkLoop>& loops, const std::vector<std::vector<Vec2>>& polys, Vec2 b0, Vec2 b1);

 private:
  // A piece is a first-pass polygon (0 .. n_loops - 1) or a bridge (n_loops + i): owner_
  // gives the loop that holds it now, pieces_of_ the pieces a loop holds.
  void start(const std::vector<std::vector<Vec2>>& polys);
  // Strikes out loop l's segment s0 -> s1 (a bridge, or a segment of a first polygon).
  void strike(std::uint32_t l, Vec2 s0, Vec2 s1);
  std::size_t n_loops_;
  std::vector<std::uint32_t> owner_;
  std::vector<std::vector<std::uint32_t>> pieces_of_;
  std::vector<std::vector<Vec2>> first_polys_;
  std::vector<std::size_t> first_at_;   // polygon l's first segment in struck_
  std::vector<char> struck_;            // per first-pass segment: replaced by a join
  std::optional<SegmentGrid> first_grid_;
  std::vector<std::vector<Vec2>> bridges_;   // each {b0, b1}: its segment 0 (segment 1 runs back)
  std::vector<char> bridge_struck_;
  std::optional<SegmentGrid> bridge_grid_;
};

}  // namespace sm::coast
