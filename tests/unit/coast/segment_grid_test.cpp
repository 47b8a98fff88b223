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
