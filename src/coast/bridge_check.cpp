#include "coast/bridge_check.h"

#include <algorithm>
#include <utility>

#include "base/check.h"
#include "exact/segments.h"

namespace sm::coast {

void BridgeCheck::start(const std::vector<std::vector<Vec2>>& polys) {
  SM_ASSERT(polys.size() == n_loops_, "BridgeCheck: polygons for another number of loops (coast/bridge_check.h)");
  first_polys_ = polys;
  first_at_.assign(polys.size() + 1, 0);
  for (std::size_t l = 0; l < polys.size(); ++l) first_at_[l + 1] = first_at_[l] + polys[l].size();
  struck_.assign(first_at_.back(), 0);
  owner_.resize(n_loops_);
  pieces_of_.assign(n_loops_, {});
  for (std::uint32_t l = 0; l < n_loops_; ++l) owner_[l] = l, pieces_of_[l].push_back(l);
  first_grid_.emplace(first_polys_);
}

void BridgeCheck::strike(std::uint32_t l, Vec2 s0, Vec2 s1) {
  // A bridge of an earlier join, which is rarely struck: looked up among the loop's pieces.
  for (const std::uint32_t piece : pieces_of_[l]) {
    if (piece < n_loops_) continue;
    const std::size_t i = piece - n_loops_;
    if (!bridge_struck_[i] && bridges_[i][0] == s0 && bridges_[i][1] == s1) {
      bridge_struck_[i] = 1;
      return;
    }
  }
  // Else a segment of a first polygon the loop holds, near its own box. The loops are
  // free of crossings and overlaps (handle_straits runs on repaired loops): one segment of
  // the loop runs from s0 to s1.
  const Vec2 lo{std::min(s0.x, s1.x), std::min(s0.y, s1.y)};
  const Vec2 hi{std::max(s0.x, s1.x), std::max(s0.y, s1.y)};
  const bool found = first_grid_->any_segment_near(lo, hi, [&](std::uint32_t p, std::uint32_t j, Vec2 a, Vec2 b) {
    char& struck = struck_[first_at_[p] + j];
    if (struck || owner_[p] != l || a != s0 || b != s1) return false;
    struck = 1;
    return true;
  });
  SM_ASSERT(found, "BridgeCheck: a joined segment is not in its loop's polygon (coast/bridge_check.cpp)");
}

void BridgeCheck::merged(const LoopJoin& j, const std::vector<std::vector<Vec2>>& polys) {
  SM_ASSERT(first_grid_.has_value(), "BridgeCheck: a join before any bridge was checked (coast/bridge_check.h)");
  const std::vector<Vec2>& pa = polys[j.into];
  const std::vector<Vec2>& pb = polys[j.from];
  SM_ASSERT(pa.size() == j.n_into && pb.size() == j.n_from,
            "BridgeCheck: a join's polygons are not the pass's (coast/bridge_check.h)");
  const Vec2 a0 = pa[j.k_into], a1 = pa[(j.k_into + 1) % j.n_into];
  const Vec2 b0 = pb[j.k_from], b1 = pb[(j.k_from + 1) % j.n_from];
  bridge_grid_.reset();   // it reads bridges_, which grows
  strike(j.into, a0, a1);
  strike(j.from, b0, b1);
  // from's pieces go to into, which also holds the two bridges (as join_polygons makes the
  // polygon: into's run ends at a0, then a0 -> b1; from's ends at b0, then b0 -> a1).
  std::vector<std::uint32_t>& to = pieces_of_[j.into];
  for (const std::uint32_t piece : pieces_of_[j.from]) {
    owner_[piece] = j.into;
    to.push_back(piece);
  }
  std::vector<std::uint32_t>().swap(pieces_of_[j.from]);
  for (const auto& [s0, s1] : {std::pair{a0, b1}, std::pair{b0, a1}}) {
    to.push_back(static_cast<std::uint32_t>(n_loops_ + bridges_.size()));
    owner_.push_back(j.into);
    bridges_.push_back({s0, s1});
    bridge_struck_.push_back(0);
  }
}

bool BridgeCheck::crosses(const std::vector<WorkLoop>& loops, const std::vector<std::vector<Vec2>>& polys, Vec2 b0,
                          Vec2 b1) {
  if (!first_grid_) start(polys);
  if (!bridge_grid_ && !bridges_.empty()) bridge_grid_.emplace(bridges_);
  const Vec2 lo{std::min(b0.x, b1.x), std::min(b0.y, b1.y)};
  const Vec2 hi{std::max(b0.x, b1.x), std::max(b0.y, b1.y)};
  // The segment s0 -> s1 of a polygon loop l held at the pass's start.
  auto meets_bridge = [&](std::uint32_t l, Vec2 s0, Vec2 s1) {
    if (loops[l].dead) return false;
    if (std::max(s0.x, s1.x) < lo.x || std::min(s0.x, s1.x) > hi.x || std::max(s0.y, s1.y) < lo.y ||
        std::min(s0.y, s1.y) > hi.y)
      return false;
    if (s0 == b0 || s0 == b1 || s1 == b0 || s1 == b1) return false;
    return segments_meet(b0, b1, s0, s1);
  };
  if (first_grid_->any_segment_near(lo, hi, [&](std::uint32_t p, std::uint32_t j, Vec2 s0, Vec2 s1) {
        return !struck_[first_at_[p] + j] && meets_bridge(owner_[p], s0, s1);
      }))
    return true;
  return bridge_grid_ && bridge_grid_->any_segment_near(lo, hi, [&](std::uint32_t i, std::uint32_t j, Vec2 s0, Vec2 s1) {
           return j == 0 && !bridge_struck_[i] && meets_bridge(owner_[n_loops_ + i], s0, s1);
         });
}

}  // namespace sm::coast
