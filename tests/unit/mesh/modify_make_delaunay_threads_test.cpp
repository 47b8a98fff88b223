// make_delaunay with threads (the parallel in-circle pre-test): the same flips, in the
// same order, as the serial flips for 1, 2 and 3 threads, on a jittered grid cut into
// triangles along one diagonal, far from Delaunay, and on one with constrained edges.
#include <doctest/doctest.h>

#include <cstring>
#include <random>

#include "mesh/check.h"
#include "mesh/modify/smooth.h"

using namespace sm;

namespace {

// An n x n grid of unit cells, each point moved by up to a quarter cell (so no triangle
// inverts), every cell cut along the same diagonal.
TriangleStore jittered_grid(std::uint32_t n) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> jitter(-0.24, 0.24);
  std::vector<Vec2> xy;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) xy.push_back({i + jitter(rng), j + jitter(rng)});
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      tris.push_back({a, b, d});
      tris.push_back({a, d, c});
    }
  TriangleStore m;
  REQUIRE(build_triangulation(xy, tris, m));
  return m;
}

bool same_corners(const TriangleStore& a, const TriangleStore& b) {
  return a.corner == b.corner && a.twin == b.twin && a.side_flags == b.side_flags;
}

}  // namespace

TEST_CASE("make_delaunay: 1, 2 and 3 threads give the same flips and bytes") {
  const TriangleStore m = jittered_grid(200);  // 80,000 triangles: several chunks
  TriangleStore one = m;
  const std::uint64_t f1 = make_delaunay(one, 1);
  CHECK(f1 > 5000);
  REQUIRE(check_topology(one).ok());
  CHECK(check_delaunay(one, PlanarGeometry{&one.xy}).ok());
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    TriangleStore x = m;
    CHECK(make_delaunay(x, threads) == f1);
    CHECK(same_corners(one, x));
  }
}

TEST_CASE("make_delaunay: constrained edges stay, for any thread count") {
  TriangleStore m = jittered_grid(150);
  // Constrain every diagonal of the first row of cells: none may flip.
  std::uint32_t constrained = 0;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    const Side o = m.twin[s];
    if (!o.valid() || m.corner[s].value > 150) continue;
    if (m.dest(Side{s}).value != m.corner[s].value + 152) continue;  // a -> d, the diagonal
    m.side_flags[s] |= kConstrained;
    m.side_flags[o.value] |= kConstrained;
    ++constrained;
  }
  REQUIRE(constrained == 150);
  TriangleStore one = m;
  const std::uint64_t f1 = make_delaunay(one, 1);
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    TriangleStore x = m;
    CHECK(make_delaunay(x, threads) == f1);
    CHECK(same_corners(one, x));
  }
  std::uint32_t still = 0;
  for (std::uint32_t s = 0; s < one.corner.size(); ++s) still += one.constrained(Side{s});
  CHECK(still == 2 * constrained);
}
