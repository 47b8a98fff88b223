// Edge collapse: an interior vertex merged onto a neighbour; refused on the
// boundary, against the link condition and when the ball would fold.
#include <doctest/doctest.h>

#include <cmath>

#include "mesh/check.h"
#include "mesh/modify/collapse.h"
#include "mesh/quality.h"

using namespace sm;

namespace {

// A hexagon (vertices 1..6) round a centre vertex 0 at c, six triangles.
TriangleStore hexagon(Vec2 c) {
  std::vector<Vec2> xy{c};
  for (int k = 0; k < 6; ++k) xy.push_back({std::cos(M_PI / 3 * k), std::sin(M_PI / 3 * k)});
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t k = 0; k < 6; ++k) tris.push_back({0, 1 + k, 1 + (k + 1) % 6});
  TriangleStore m;
  REQUIRE(build_triangulation(xy, tris, m));
  return m;
}

}  // namespace

TEST_CASE("collapse: ring of an interior and of a hull vertex") {
  TriangleStore m = hexagon({0, 0});
  std::vector<Side> ring;
  CHECK(vertex_ring(m, VertexId{0}, ring) == FanEnd::Closed);
  CHECK(ring.size() == 6);
  for (std::size_t i = 0; i + 1 < ring.size(); ++i)  // counter-clockwise order
    CHECK(m.dest(ring[i + 1]) == m.apex(ring[i]));
  CHECK(vertex_ring(m, VertexId{1}, ring) == FanEnd::Open);
  CHECK(ring.size() == 2);
  CHECK(m.dest(ring[1]) == m.apex(ring[0]));
}

TEST_CASE("collapse: an open ring starts clockwise-most whatever out_side names") {
  TriangleStore m = hexagon({0, 0});
  m.kill_triangle(TriId{3});  // (0, 4, 5): the centre's fan opens between 4 and 5
  for (std::uint32_t t : {0u, 1u, 2u, 4u, 5u}) {
    m.out_side[0] = side_of(TriId{t}, 0);
    std::vector<Side> ring;
    REQUIRE(vertex_ring(m, VertexId{0}, ring) == FanEnd::Open);
    REQUIRE(ring.size() == 5);
    CHECK(m.dest(ring.front()) == VertexId{5});
    CHECK(m.apex(ring.back()) == VertexId{4});
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) CHECK(m.dest(ring[i + 1]) == m.apex(ring[i]));
  }
}

TEST_CASE("collapse: a corrupt fan is refused, not walked") {
  TriangleStore m = hexagon({0.1, 0.05});
  // Triangles 2 and 3 point at each other round the centre: counter-clockwise from
  // triangle 0 the walk enters the loop 2 -> 3 -> 2 and never comes back.
  m.twin[prev(side_of(TriId{3}, 0)).value] = side_of(TriId{2}, 0);
  std::vector<Side> ring;
  m.out_side[0] = side_of(TriId{0}, 0);
  CHECK(vertex_ring(m, VertexId{0}, ring) == FanEnd::Corrupt);
  CHECK(ring.empty());
  CHECK(can_collapse(m, m.side_between(VertexId{0}, VertexId{1}), ring) == CollapseCheck::CorruptFan);
}

TEST_CASE("collapse: centre of a hexagon onto a corner") {
  TriangleStore m = hexagon({0.1, 0.05});
  const Side s = m.side_between(VertexId{0}, VertexId{1});
  std::vector<Side> ring;
  REQUIRE(can_collapse(m, s, ring) == CollapseCheck::Ok);
  collapse_edge(m, s, ring);
  CHECK(m.num_triangles() == 4);
  CHECK_FALSE(m.out_side[0].valid());
  for (std::uint32_t u = 3; u <= 5; ++u) CHECK(m.has_edge(VertexId{1}, VertexId{u}));
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  const auto map = drop_isolated_vertices(m);
  CHECK(map[0] == VertexId::kNone);
  CHECK(map[1] == 0);
  CHECK(m.num_vertices() == 6);
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  CHECK(mesh_quality(m).nodes == 6);
}

TEST_CASE("collapse: refusals") {
  std::vector<Side> ring;
  SUBCASE("boundary vertex") {
    TriangleStore m = hexagon({0, 0});
    CHECK(can_collapse(m, m.side_between(VertexId{1}, VertexId{0}), ring) == CollapseCheck::Constrained);
  }
  SUBCASE("vertex on a constrained edge") {
    TriangleStore m = hexagon({0, 0});
    m.set_edge_flags(m.side_between(VertexId{0}, VertexId{4}), kConstrained);
    CHECK(can_collapse(m, m.side_between(VertexId{0}, VertexId{1}), ring) == CollapseCheck::Constrained);
  }
  SUBCASE("the ball would fold") {
    // Centre 0 at the origin, a non-convex ring: from corner 1 at (2, 0)
    // the ring edge 2-3 is seen from behind, from corner 2 everything is.
    TriangleStore m;
    REQUIRE(build_triangulation({{0, 0}, {2, 0}, {0, 0.3}, {-1, 1}, {-1, -1}, {0, -0.3}},
                                {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1}}, m));
    CHECK(can_collapse(m, m.side_between(VertexId{0}, VertexId{1}), ring) == CollapseCheck::Inverted);
    CHECK(can_collapse(m, m.side_between(VertexId{0}, VertexId{3}), ring) == CollapseCheck::Inverted);
    CHECK(can_collapse(m, m.side_between(VertexId{0}, VertexId{4}), ring) == CollapseCheck::Inverted);
    const Side s = m.side_between(VertexId{0}, VertexId{2});
    REQUIRE(can_collapse(m, s, ring) == CollapseCheck::Ok);
    collapse_edge(m, s, ring);
    CHECK(m.num_triangles() == 3);
    INFO(check_topology(m).error);
    CHECK(check_topology(m).ok());
  }
  SUBCASE("link condition") {
    // Square 1..4 round a separating triangle 0, 5, 6 with vertex 7 inside:
    // 6 neighbours both 0 and 5 but is no apex of edge 0-5, so collapsing it
    // would make the edge 0-6 twice.
    TriangleStore m;
    REQUIRE(build_triangulation({{-1, -0.5}, {-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {1, -0.5}, {0, 1}, {0, 0}},
                                {{0, 5, 7}, {5, 6, 7}, {6, 0, 7}, {1, 2, 5}, {1, 5, 0}, {2, 3, 5}, {3, 6, 5},
                                 {3, 4, 6}, {4, 0, 6}, {4, 1, 0}},
                                m));
    REQUIRE(check_topology(m).ok());
    CHECK(can_collapse(m, m.side_between(VertexId{0}, VertexId{5}), ring) == CollapseCheck::Link);
    CHECK(can_collapse(m, m.side_between(VertexId{5}, VertexId{0}), ring) == CollapseCheck::Link);
    // Vertex 7 (degree 3) onto 0 is fine: the apexes 5 and 6 are its only other neighbours.
    const Side s = m.side_between(VertexId{7}, VertexId{0});
    REQUIRE(can_collapse(m, s, ring) == CollapseCheck::Ok);
    collapse_edge(m, s, ring);
    CHECK(m.num_triangles() == 8);
    INFO(check_topology(m).error);
    CHECK(check_topology(m).ok());
  }
}
