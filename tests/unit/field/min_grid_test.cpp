#include "field/min_grid.h"

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>

#include <doctest/doctest.h>

using namespace sm;
using namespace sm::field;

TEST_CASE("min grid: the bound never exceeds the smallest value within r, on a plane and on a sphere") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), val(0, 10), lr(-6, 0.5);
  for (const bool sphere : {false, true}) {
    std::vector<Vec3> pts(3000);
    std::vector<double> v(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      Vec3 p{u(rng), u(rng), sphere ? u(rng) : 0.25};
      if (sphere) p = (6.371e6 / norm(p)) * p;
      pts[i] = p;
      v[i] = val(rng);
    }
    const double scale = sphere ? 6.371e6 : 1;
    MinGrid grid(pts, v, 0.01 * scale);
    CHECK(grid.cells() >= pts.size());
    int bounded = 0;
    for (int q = 0; q < 3000; ++q) {
      // Queries near the points (some exactly on one) and far from them.
      Vec3 x = q % 3 == 0 ? pts[static_cast<std::size_t>(q)] : Vec3{u(rng), u(rng), u(rng)} * (1.5 * scale);
      const double r = std::pow(10.0, lr(rng)) * scale;
      double least = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < pts.size(); ++i)
        if (norm(pts[i] - x) <= r) least = std::min(least, v[i]);
      const double b = grid.lower_bound(x, r);
      CHECK(b <= least);
      // The early-exit test agrees with the bound, on each side of it.
      for (const double w : {b, std::nextafter(b, -1e300), std::nextafter(b, 1e300), 0.5 * b, 2 * b})
        CHECK(grid.at_least(x, r, w) == (b >= w));
      bounded += std::isfinite(b) && b > 0;
    }
    // The grid is not trivially -inf: small balls get real bounds.
    CHECK(bounded > 500);
  }
}

TEST_CASE("min grid: a point exactly r away is inside, a far ball is empty, bad queries give no bound") {
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}};
  const std::vector<double> v{5, 2};
  MinGrid grid(pts, v, 0.1);
  CHECK(grid.lower_bound({0.5, 0, 0}, 0.5) == 2);
  CHECK(grid.lower_bound({-0.3, 0, 0}, 0.3) == 5);
  CHECK(grid.lower_bound({40, 40, 40}, 0.3) == std::numeric_limits<double>::infinity());
  CHECK(grid.lower_bound({0, 0, 0}, 1e9) == -std::numeric_limits<double>::infinity());
  CHECK(grid.lower_bound({std::nan(""), 0, 0}, 0.1) == -std::numeric_limits<double>::infinity());
  MinGrid empty({}, {}, 1);
  CHECK(empty.lower_bound({0, 0, 0}, 1) == std::numeric_limits<double>::infinity());
}

TEST_CASE("min grid: the same bounds for every thread count") {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1), val(0, 10);
  // Enough points for the cells' sort to run in several runs, many in shared cells.
  std::vector<Vec3> pts(200000);
  std::vector<double> v(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = {u(rng), u(rng), 0.5 * u(rng)}, v[i] = val(rng);
  const MinGrid one(pts, v, 0.003, 1);
  for (const int threads : {2, 4}) {
    const MinGrid many(pts, v, 0.003, threads);
    CHECK(many.cells() == one.cells());
    for (int q = 0; q < 2000; ++q) {
      const Vec3 x{u(rng), u(rng), u(rng)};
      const double r = 0.002 * (1 + q % 50);
      CHECK(many.lower_bound(x, r) == one.lower_bound(x, r));
    }
  }
}

TEST_CASE("min grid: a ball inside one cell reads that cell's smallest value, at every level (brute force)") {
  // The table places the 8 cells of a brick in one group of slots (field/min_grid.cpp): a
  // cell stored where a query does not look for it would read +inf, above the value. The
  // points' corner is the origin and the cells are powers of two, so the cells' bounds
  // are exact and each point's cell is known here.
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> u(0, 1), val(0, 10);
  const double finest = 1.0 / 64;
  for (const bool curve : {false, true}) {
    // A cloud that fills most bricks, or points along a curve (a coast) that leaves most
    // of each brick's cells empty.
    std::vector<Vec3> pts{{0, 0, 0}};
    for (int n = 0; n < 20000; ++n) {
      const double t = u(rng);
      pts.push_back(curve ? Vec3{t, 0.5 + 0.4 * std::sin(9 * t), 0.05 + 0.02 * std::cos(5 * t)}
                          : Vec3{t, u(rng), 0.1 * u(rng)});
    }
    std::vector<double> v(pts.size());
    for (double& x : v) x = val(rng);
    const MinGrid grid(pts, v, finest);
    for (int level = 0; level < 7; ++level) {
      const std::int64_t per_cell = std::int64_t{1} << level;
      const double cell = finest * static_cast<double>(per_cell);
      std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, double> least;
      for (std::size_t n = 0; n < pts.size(); ++n) {
        const auto at = [&](double c) { return static_cast<std::int64_t>(std::floor(c / finest)) >> level; };
        const auto key = std::make_tuple(at(pts[n].x), at(pts[n].y), at(pts[n].z));
        const auto it = least.find(key);
        if (it == least.end()) {
          least.emplace(key, v[n]);
        } else {
          it->second = std::min(it->second, v[n]);
        }
      }
      const auto centre = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        return Vec3{(static_cast<double>(i) + 0.5) * cell, (static_cast<double>(j) + 0.5) * cell,
                    (static_cast<double>(k) + 0.5) * cell};
      };
      for (const auto& [ijk, m] : least) {
        const auto [i, j, k] = ijk;
        float f = static_cast<float>(m);
        if (static_cast<double>(f) > m) f = std::nextafter(f, -1e30f);
        const double expected = f;
        const Vec3 x = centre(i, j, k);
        REQUIRE(grid.lower_bound(x, 0.3 * cell) == expected);
        CHECK(grid.at_least(x, 0.3 * cell, expected));
        CHECK_FALSE(grid.at_least(x, 0.3 * cell, std::nextafter(expected, 1e300)));
      }
      // The cells beside held ones that hold no point read +inf.
      int empty = 0;
      for (const auto& [ijk, m] : least) {
        const auto [i, j, k] = ijk;
        for (const std::int64_t dk : {-1, 1}) {
          if (k + dk < 0 || least.count({i, j, k + dk}) > 0) continue;
          CHECK(grid.lower_bound(centre(i, j, k + dk), 0.3 * cell) == std::numeric_limits<double>::infinity());
          ++empty;
        }
      }
      CHECK(empty > 0);
    }
  }
}
