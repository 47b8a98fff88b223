// The dual graph of the 2D elements: an edge per mesh side shared by two elements,
// symmetric, in a fixed order.
#include <doctest/doctest.h>

#include <algorithm>

#include "io/dual_graph.h"
#include "io/test_meshes.h"

TEST_CASE("dual graph: one edge per interior side of a grid, symmetric, sorted") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    const sm::io::MeshModel m = sm::io::testing::grid_square(n);
    const sm::io::DualGraph g = sm::io::dual_graph_2d(m);
    REQUIRE(g.size() == static_cast<std::size_t>(2 * n * n));
    REQUIRE(g.xadj.size() == g.size() + 1);
    // n x n squares cut by a diagonal: 3n^2 + 2n sides, 4n of them on the boundary.
    CHECK(g.adjncy.size() == static_cast<std::size_t>(2 * (3 * n * n - 2 * n)));
    for (std::size_t v = 0; v < g.size(); ++v) {
      const auto begin = g.adjncy.begin() + g.xadj[v], end = g.adjncy.begin() + g.xadj[v + 1];
      CHECK(end - begin >= 1);
      CHECK(end - begin <= 3);
      CHECK(std::is_sorted(begin, end));
      for (auto it = begin; it != end; ++it) {
        CHECK(static_cast<std::size_t>(*it) != v);
        const std::size_t w = static_cast<std::size_t>(*it);
        const auto wb = g.adjncy.begin() + g.xadj[w], we = g.adjncy.begin() + g.xadj[w + 1];
        CHECK(std::find(wb, we, static_cast<std::int32_t>(v)) != we);   // symmetric
      }
    }
    // Vertices are the surface's triangles in order.
    for (std::size_t v = 0; v < g.size(); ++v) CHECK(g.elements[v].second == v);
  }
}

TEST_CASE("dual graph: two triangles on a side are neighbours, across surfaces too") {
  sm::io::MeshModel m;
  m.xyz = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  sm::io::EntityMesh a, b;
  a.dim = b.dim = 2, a.tag = 1, b.tag = 2;
  a.type = b.type = sm::io::ElementType::Triangle3;
  a.connectivity = {0, 1, 2};
  b.connectivity = {0, 2, 3};
  m.entities = {b, a};   // listed out of order: the graph follows (dim, tag)
  const sm::io::DualGraph g = sm::io::dual_graph_2d(m);
  REQUIRE(g.size() == 2);
  CHECK(g.elements[0].first == 1);   // surface 1 first
  CHECK(g.adjncy == std::vector<std::int32_t>{1, 0});
  CHECK(g.xadj == std::vector<std::int32_t>{0, 1, 2});
}

TEST_CASE("dual graph: no 2D element, no vertex") {
  sm::io::MeshModel m = sm::io::testing::grid_square(2);
  m.entities.pop_back();   // the surface
  CHECK(sm::io::dual_graph_2d(m).size() == 0);
}
