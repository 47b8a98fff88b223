// BridgeCheck (coast/bridge_check.h): its first-pass grid, kept through the passes and told
// each join, answers every bridge as a check against the pass's polygons themselves would
// (the oracle: every segment of a loop alive now, those sharing an end point with the
// bridge left out), through passes of joins made as handle_straits makes them (repair.cpp,
// join_polygons), bridges of earlier joins replaced by later ones among them.
#include "coast/bridge_check.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "exact/segments.h"

using namespace sm;
using namespace sm::coast;

namespace {

// The oracle: the bridge against every segment of the polygons of the loops alive now.
bool crosses_any(const std::vector<WorkLoop>& loops, const std::vector<std::vector<Vec2>>& polys, Vec2 b0, Vec2 b1) {
  for (std::size_t l = 0; l < polys.size(); ++l) {
    if (loops[l].dead) continue;
    const std::vector<Vec2>& p = polys[l];
    for (std::size_t j = 0; j < p.size(); ++j) {
      const Vec2 s0 = p[j], s1 = p[(j + 1) % p.size()];
      if (s0 == b0 || s0 == b1 || s1 == b0 || s1 == b1) continue;
      if (segments_meet(b0, b1, s0, s1)) return true;
    }
  }
  return false;
}

// The joined polygon as LoopJoin describes it (coast/intersections.h): into's vertices from
// k_into + 1 round, then from's from k_from + 1 round; from's polygon emptied.
void join(std::vector<std::vector<Vec2>>& polys, const LoopJoin& j) {
  std::vector<Vec2> p;
  for (const auto [l, k, n] : {std::array{j.into, j.k_into, j.n_into}, std::array{j.from, j.k_from, j.n_from}})
    for (std::uint32_t i = 0; i < n; ++i) p.push_back(polys[l][(k + 1 + i) % n]);
  polys[j.into] = std::move(p);
  polys[j.from].clear();
}

}  // namespace

TEST_CASE("bridge check: the grid kept from the first pass and told the joins answers as the pass's polygons") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(0.0, 10.0), step(-0.5, 0.5), reach(-1.0, 1.0);
  const std::size_t n_loops = 60;
  std::vector<std::vector<Vec2>> polys(n_loops);
  std::vector<WorkLoop> loops(n_loops);
  for (std::size_t l = 0; l < n_loops; ++l) {
    Vec2 x{at(rng), at(rng)};
    const int n = 3 + static_cast<int>(rng() % 25);
    for (int i = 0; i < n; ++i) polys[l].push_back(x), x = x + Vec2{step(rng), step(rng)};
  }
  polys[9].clear();   // a loop dead from the start: no polygon
  loops[9].dead = true;
  BridgeCheck check(n_loops);
  std::size_t yes = 0, no = 0, joins_made = 0, bridges_replaced = 0;
  // A bridge from a vertex of a live loop (as handle_straits' are) or anywhere.
  auto random_end = [&]() -> Vec2 {
    const std::size_t l = rng() % n_loops;
    if (polys[l].empty() || rng() % 3 == 0) return {at(rng), at(rng)};
    return polys[l][rng() % polys[l].size()];
  };
  auto ask = [&] {
    const Vec2 b0 = random_end();
    const Vec2 b1 = rng() % 2 ? random_end() : b0 + Vec2{reach(rng), reach(rng)};
    const bool want = crosses_any(loops, polys, b0, b1);
    CHECK(check.crosses(loops, polys, b0, b1) == want);
    (want ? yes : no) += 1;
  };
  std::vector<LoopJoin> joins;
  std::vector<std::vector<char>> is_bridge(n_loops);   // per loop and segment: a bridge of an earlier join
  for (std::size_t l = 0; l < n_loops; ++l) is_bridge[l].assign(polys[l].size(), 0);
  for (int pass = 0; pass < 12; ++pass) {
    for (const LoopJoin& j : joins) {
      check.merged(j, polys);
      bridges_replaced += is_bridge[j.into][j.k_into] + is_bridge[j.from][j.k_from];
      // The bridges' flags turned as the vertices are: the new bridges at n_into - 1 and at the end.
      std::vector<char> flags;
      for (const auto [l, k, n] : {std::array{j.into, j.k_into, j.n_into}, std::array{j.from, j.k_from, j.n_from}})
        for (std::uint32_t i = 0; i < n; ++i) flags.push_back(is_bridge[l][(k + 1 + i) % n]);
      flags[j.n_into - 1] = flags.back() = 1;
      join(polys, j);
      is_bridge[j.into] = std::move(flags);
      is_bridge[j.from].clear();
    }
    joins.clear();
    check.new_pass();
    std::vector<char> changed(n_loops, 0);
    for (int q = 0; q < 150; ++q) {
      ask();
      if (q % 8 != 7) continue;
      // A join of two loops alive and unchanged in this pass: `from` dies now, into's
      // polygon stays the pass's until the next pass.
      const auto a = static_cast<std::uint32_t>(rng() % n_loops), b = static_cast<std::uint32_t>(rng() % n_loops);
      if (a == b || loops[a].dead || loops[b].dead || changed[a] || changed[b]) continue;
      const auto na = static_cast<std::uint32_t>(polys[a].size()), nb = static_cast<std::uint32_t>(polys[b].size());
      // Half the time across a bridge of an earlier join, when the loop has one.
      auto pick = [&](std::uint32_t l, std::uint32_t n) {
        std::vector<std::uint32_t> on_bridge;
        for (std::uint32_t t = 0; t < n; ++t)
          if (is_bridge[l][t]) on_bridge.push_back(t);
        if (!on_bridge.empty() && rng() % 2) return on_bridge[rng() % on_bridge.size()];
        return static_cast<std::uint32_t>(rng() % n);
      };
      joins.push_back({a, b, pick(a, na), pick(b, nb), na, nb});
      loops[b].dead = true;
      changed[a] = changed[b] = 1;
      ++joins_made;
    }
  }
  CHECK(joins_made > 30);
  CHECK(bridges_replaced > 10);
  CHECK(yes > 500);
  CHECK(no > 100);
}
