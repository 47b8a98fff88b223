// Edge split: interior and hull edges, constrained edges only when allowed,
// refused when a new triangle would be flat or clockwise.
#include <doctest/doctest.h>

#include "mesh/check.h"
#include "mesh/modify/split.h"
#include "mesh/quality.h"
#include "testing_domains.h"

using namespace sm;

namespace {

// Unit square cut along the diagonal 0-2.
TriangleStore split_square() {
  TriangleStore m;
  REQUIRE(build_triangulation({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}, m));
  return m;
}

}  // namespace

TEST_CASE("split: interior edge at its midpoint") {
  TriangleStore m = split_square();
  const Side s = m.side_between(VertexId{0}, VertexId{2});
  REQUIRE(s.valid());
  const VertexId v = split_edge(m, s, {0.5, 0.5});
  REQUIRE(v.valid());
  CHECK(v.value == 4);
  CHECK(m.num_triangles() == 4);
  for (std::uint32_t u = 0; u < 4; ++u) CHECK(m.has_edge(v, VertexId{u}));
  CHECK_FALSE(m.has_edge(VertexId{0}, VertexId{2}));
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  CHECK(check_delaunay(m, PlanarGeometry{&m.xy}).ok());
}

TEST_CASE("split: hull edge, then flags of a constrained edge follow both halves") {
  TriangleStore m = split_square();
  const Side hull = m.side_between(VertexId{0}, VertexId{1});
  REQUIRE(hull.valid());
  const VertexId v = split_edge(m, hull, {0.5, 0});
  REQUIRE(v.valid());
  CHECK(m.num_triangles() == 3);
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  // Constrain the diagonal: refused unless allowed, then both halves keep the flag.
  Side d = m.side_between(VertexId{0}, VertexId{2});
  REQUIRE(d.valid());
  m.set_edge_flags(d, kConstrained | kBoundary);
  CHECK_FALSE(split_edge(m, d, {0.5, 0.5}).valid());
  CHECK(m.num_triangles() == 3);
  const VertexId w = split_edge(m, d, {0.5, 0.5}, /*allow_constrained=*/true);
  REQUIRE(w.valid());
  CHECK(check_constraints(m, {{VertexId{0}, w}, {w, VertexId{2}}}).ok());
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
}

TEST_CASE("split: a point off the edge that would fold a triangle is refused") {
  TriangleStore m = split_square();
  const Side s = m.side_between(VertexId{0}, VertexId{2});
  const auto before = m.corner;
  // Beyond vertex 1: triangle (p, 1, 2) would turn clockwise.
  CHECK_FALSE(split_edge(m, s, {1.2, -0.2}).valid());
  // Exactly on the line through 1 and 2 (x = 1): flat triangle, refused by the exact test.
  CHECK_FALSE(split_edge(m, s, {1, 0.5}).valid());
  CHECK(m.corner == before);
  CHECK(m.num_vertices() == 4);
  CHECK(check_topology(m).ok());
}

TEST_CASE("split: repeated midpoint splits of a recovered domain stay valid") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, false);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  // Split the longest interior edge of every triangle five times over.
  for (int round = 0; round < 5; ++round) {
    const std::uint32_t slots = m.num_slots();
    for (std::uint32_t t = 0; t < slots; ++t) {
      if (!m.alive(TriId{t})) continue;
      Side best;
      double len = 0;
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side s = side_of(TriId{t}, e);
        const double l = norm(m.pos(m.dest(s)) - m.pos(m.org(s)));
        if (!m.constrained(s) && l > len) len = l, best = s;
      }
      if (best.valid()) split_edge(m, best, 0.5 * (m.pos(m.org(best)) + m.pos(m.dest(best))));
    }
    INFO(check_topology(m).error);
    REQUIRE(check_topology(m).ok());
    REQUIRE(check_constraints(m, edges).ok());
  }
  double area = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t})) {
      const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
      area += 0.5 * cross(b - a, c - a);
    }
  CHECK(area == doctest::Approx(1.0));
  CHECK(m.num_triangles() > 100);
}
