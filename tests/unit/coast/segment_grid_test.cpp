// SegmentGrid (coast/segment_grid.h): every segment whose box meets a query box is visited,
// each once per query, with the polygon it belongs to; an oracle over all segments.
#include "coast/segment_grid.h"

#include <doctest/doctest.h>

#include <map>
#include <random>
#include <utility>
#include <vector>

using namespace sm;
using namespace sm::coast;

TEST_CASE("segment grid: every segment whose box meets the query's is visited once, with its polygon") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> at(-3.0, 5.0), step(-0.2, 0.2), side(0.0, 0.6);
  std::vector<std::vector<Vec2>> polys(40);
  for (auto& p : polys) {
    Vec2 x{at(rng), at(rng)};
    const int n = 3 + static_cast<int>(rng() % 30);
    for (int i = 0; i < n; ++i) p.push_back(x), x = x + Vec2{step(rng), step(rng)};
  }
  polys[7].clear();   // a dead loop's polygon: no segment
  SegmentGrid grid(polys);
  std::size_t met = 0;   // segments the queries' boxes met: the oracle's check ran
  for (int q = 0; q < 300; ++q) {
    const Vec2 lo{at(rng), at(rng)};
    const Vec2 hi = lo + Vec2{side(rng), side(rng)};
    std::map<std::pair<std::size_t, std::size_t>, int> seen;
    const bool any = grid.any_near_in(lo, hi, [&](std::uint32_t l, Vec2 s0, Vec2 s1) {
      const auto& p = polys[l];
      bool found = false;
      for (std::size_t j = 0; j < p.size() && !found; ++j)
        if (p[j] == s0 && p[(j + 1) % p.size()] == s1) ++seen[{l, j}], found = true;
      CHECK(found);   // the segment is one of polygon l's
      return false;
    });
    CHECK_FALSE(any);
    for (const auto& [key, count] : seen) CHECK(count == 1);
    for (std::size_t l = 0; l < polys.size(); ++l)
      for (std::size_t j = 0; j < polys[l].size(); ++j) {
        const Vec2 a = polys[l][j], b = polys[l][(j + 1) % polys[l].size()];
        const bool meets = std::max(a.x, b.x) >= lo.x && std::min(a.x, b.x) <= hi.x && std::max(a.y, b.y) >= lo.y &&
                           std::min(a.y, b.y) <= hi.y;
        if (!meets) continue;
        CHECK(seen.count({l, j}) == 1);
        ++met;
      }
  }
  CHECK(met > 100);
  // The first segment f accepts ends the query.
  int calls = 0;
  CHECK(grid.any_near({-10, -10}, {10, 10}, [&](Vec2, Vec2) { return ++calls == 3; }));
  CHECK(calls == 3);
  const std::vector<std::vector<Vec2>> none(3);
  SegmentGrid empty(none);
  CHECK_FALSE(empty.any_near({0, 0}, {1, 1}, [](Vec2, Vec2) { return true; }));
}

TEST_CASE("segment grid: a dense place is cut finer, so a small query there reads few segments") {
  // One wide polygon and a cluster of 4,000 short segments in a corner a thousandth of its
  // size (the coast near the map's centre against the far north): the coarse cells there
  // hold the whole cluster; a query the size of one segment reads a handful of them, and
  // still every segment its box meets (the oracle).
  std::vector<std::vector<Vec2>> polys;
  polys.push_back({{-100, -100}, {100, -100}, {100, 100}, {-100, 100}});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> in(0.0, 0.1), step(-0.001, 0.001);
  for (int r = 0; r < 400; ++r) {
    std::vector<Vec2> p;
    Vec2 x{in(rng), in(rng)};
    for (int i = 0; i < 10; ++i) p.push_back(x), x = x + Vec2{step(rng), step(rng)};
    polys.push_back(p);
  }
  SegmentGrid grid(polys);
  std::uniform_real_distribution<double> q(0.0, 0.1);
  std::size_t found = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec2 lo{q(rng), q(rng)}, hi = lo + Vec2{0.002, 0.002};
    std::size_t want = 0, got = 0;
    for (const auto& p : polys)
      for (std::size_t j = 0; j < p.size(); ++j) {
        const Vec2 a = p[j], b = p[(j + 1) % p.size()];
        want += std::max(a.x, b.x) >= lo.x && std::min(a.x, b.x) <= hi.x && std::max(a.y, b.y) >= lo.y &&
                std::min(a.y, b.y) <= hi.y;
      }
    grid.any_near(lo, hi, [&](Vec2 a, Vec2 b) {
      got += std::max(a.x, b.x) >= lo.x && std::min(a.x, b.x) <= hi.x && std::max(a.y, b.y) >= lo.y &&
             std::min(a.y, b.y) <= hi.y;
      return false;
    });
    CHECK(got == want);
    found += want;
  }
  CHECK(found > 200);
  // 200 queries: about a hundred segments each at most, where the coarse cells alone gave
  // the whole cluster (4,000) to every one.
  CHECK(grid.visited() < 200 * 100);
}
