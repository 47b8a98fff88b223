// Laplacian smoothing + Lawson flips after del2d: the mesh stays valid,
// constrained Delaunay, and its quality improves.
#include <doctest/doctest.h>

#include "mesh/check.h"
#include "mesh/modify/smooth.h"
#include "mesh/quality.h"
#include "mesh/refine.h"
#include "testing_domains.h"

using namespace sm;

namespace {

// The unit square's boundary and del2d at h = 0.05 (its boundary vertices first).
Loop refined_unit_square(TriangleStore& m) {
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.05, false);
  REQUIRE(testing::boundary_mesh(m, {sq}, nullptr));
  RefineOptions opt;
  opt.size = 0.05;
  REQUIRE(refine_del2d(m, opt).ok());
  return sq;
}

}  // namespace

TEST_CASE("smooth: one and three passes after del2d on a square with a hole") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.02, false);
  const Loop hole = testing::circle_loop(m, {0.4, 0.6}, 0.15, 0.02, true);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq, hole}, &edges));
  RefineOptions opt;
  opt.size = 0.02;
  REQUIRE(refine_del2d(m, opt).ok());
  const auto before = mesh_quality(m);
  const std::vector<Vec2> boundary_xy = m.xy;
  const auto st = smooth_laplacian(m, 1);
  CHECK(st.moved > 1000);
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  REQUIRE(check_constraints(m, edges).ok());
  REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
  const auto after = mesh_quality(m);
  MESSAGE("rho > 0.9: " << before.share_rho_09 << " -> " << after.share_rho_09 << ", min rho " << before.min_rho
                        << " -> " << after.min_rho);
  CHECK(after.share_rho_09 > before.share_rho_09 + 0.1);
  CHECK(after.triangles == before.triangles);
  // Boundary vertices never move.
  for (const Loop* l : {&sq, &hole})
    for (VertexId v : l->v) CHECK(m.xy[v.value] == boundary_xy[v.value]);
  smooth_laplacian(m, 2);
  REQUIRE(check_topology(m).ok());
  REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
  CHECK(mesh_quality(m).share_rho_09 >= after.share_rho_09);
}

TEST_CASE("smooth: pinned vertices stay, the others move as without pinning") {
  // The face mesher pins its input vertices when it has embedded points (on no
  // constrained edge): the same smoothing, one implementation.
  TriangleStore m;
  const Loop sq = refined_unit_square(m);
  const std::uint32_t pinned = static_cast<std::uint32_t>(sq.v.size()) + 5;   // 5 interior vertices too
  TriangleStore free_copy = m;
  const std::vector<Vec2> before = m.xy;
  smooth_laplacian(m, 1, 1, pinned);
  smooth_laplacian(free_copy, 1);
  for (std::uint32_t v = 0; v < pinned; ++v) CHECK(m.xy[v] == before[v]);
  std::uint32_t moved_free = 0;
  for (std::uint32_t v = sq.v.size(); v < pinned; ++v) moved_free += !(free_copy.xy[v] == before[v]);
  CHECK(moved_free > 0);   // without the pin they would have moved
  REQUIRE(check_topology(m).ok());
  REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
}

TEST_CASE("smooth: the ends of an inner constrained edge stay, whichever side holds the flag") {
  TriangleStore m;
  const Loop sq = refined_unit_square(m);
  const std::uint32_t first_inner = static_cast<std::uint32_t>(sq.v.size());
  Side s{0};
  while (s.value < m.corner.size() && !(m.alive(tri_of(s)) && m.twin[s.value].valid() &&
                                        m.org(s).value >= first_inner && m.dest(s).value >= first_inner))
    ++s.value;
  REQUIRE(s.value < m.corner.size());
  const VertexId a = m.org(s), b = m.dest(s);
  TriangleStore free_copy = m;
  smooth_laplacian(free_copy, 1);
  CHECK((!(free_copy.xy[a.value] == m.xy[a.value]) || !(free_copy.xy[b.value] == m.xy[b.value])));
  for (const Side flagged : {s, m.twin[s.value]})
    for (int threads : {1, 2}) {
      CAPTURE(threads);
      TriangleStore x = m;
      x.side_flags[flagged.value] |= kConstrained;
      auto flagged_sides = [&x] {
        std::uint32_t n = 0;
        for (std::uint32_t k = 0; k < x.corner.size(); ++k) n += x.constrained(Side{k});
        return n;
      };
      const std::uint32_t flagged_before = flagged_sides();
      smooth_laplacian(x, 1, threads);
      CHECK(x.xy[a.value] == m.xy[a.value]);
      CHECK(x.xy[b.value] == m.xy[b.value]);
      // A flag on one side only fails check_topology; the flips still keep the edge.
      CHECK(flagged_sides() == flagged_before);
    }
}
