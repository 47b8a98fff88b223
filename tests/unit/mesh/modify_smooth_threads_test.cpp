// smooth_laplacian with threads: the same bytes for 1, 2 and 4 threads, on a refined
// square and on a star whose Laplacian move would invert a triangle (undone).
#include <doctest/doctest.h>

#include <cstring>

#include "mesh/check.h"
#include "mesh/modify/smooth.h"
#include "mesh/refine.h"
#include "testing_domains.h"

using namespace sm;

namespace {

bool same_points_and_corners(const TriangleStore& a, const TriangleStore& b) {
  return a.xy.size() == b.xy.size() && std::memcmp(a.xy.data(), b.xy.data(), a.xy.size() * sizeof(Vec2)) == 0 &&
         a.corner == b.corner && a.twin == b.twin;
}

}  // namespace

TEST_CASE("smooth_laplacian: 1, 2 and 4 threads give the same bytes and counts") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.004, false);
  const Loop hole = testing::circle_loop(m, {0.4, 0.6}, 0.15, 0.004, true);
  REQUIRE(testing::boundary_mesh(m, {sq, hole}));
  RefineOptions opt;
  opt.size = 0.004;
  REQUIRE(refine_del2d(m, opt).ok());
  REQUIRE(m.num_vertices() > 40000);  // several chunks of 16384 vertices
  TriangleStore one = m;
  const SmoothStats s1 = smooth_laplacian(one, 2, 1);
  CHECK(s1.moved > 50000);
  REQUIRE(check_topology(one).ok());
  for (int threads : {2, 4}) {
    CAPTURE(threads);
    TriangleStore x = m;
    const SmoothStats sx = smooth_laplacian(x, 2, threads);
    CHECK(same_points_and_corners(one, x));
    CHECK(sx.moved == s1.moved);
    CHECK(sx.refused == s1.refused);
    CHECK(sx.flips == s1.flips);
  }
}

TEST_CASE("smooth_laplacian: a move that would invert a triangle is undone, for any thread count") {
  // v at the origin; its ring has two far vertices on the right and reflex vertices near
  // v, so the mean of the ring (3.07, 0) cannot see the edge (0.2, 0.2) - (-1, 1).
  const std::vector<Vec2> xy = {{0, 0}, {10, -1}, {10, 1}, {0.2, 0.2}, {-1, 1}, {-1, -1}, {0.2, -0.2}};
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t k = 1; k <= 6; ++k) tris.push_back({0, k, k % 6 + 1});
  for (int threads : {1, 3}) {
    CAPTURE(threads);
    TriangleStore m;
    REQUIRE(build_triangulation(xy, tris, m));
    const SmoothStats st = smooth_laplacian(m, 1, threads);
    CHECK(st.refused == 1);
    CHECK(st.moved == 0);
    CHECK(m.xy[0] == Vec2{0, 0});
    CHECK(check_topology(m).ok());
  }
}
