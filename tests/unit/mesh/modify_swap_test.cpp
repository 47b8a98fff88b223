// Quality swap: a flat pair is swapped, a good pair or a non-convex quad is
// not, constrained edges never; the pass raises the worst quality.
#include <doctest/doctest.h>

#include "mesh/check.h"
#include "mesh/modify/split.h"
#include "mesh/modify/swap.h"
#include "mesh/quality.h"
#include "testing_domains.h"

using namespace sm;

TEST_CASE("swap: the short diagonal of a flat rhombus wins") {
  // Rhombus 0 (0,0), 1 (2,-0.4), 2 (4,0), 3 (2,0.4) cut along the long diagonal 0-2.
  TriangleStore m;
  REQUIRE(build_triangulation({{0, 0}, {2, -0.4}, {4, 0}, {2, 0.4}}, {{0, 1, 2}, {0, 2, 3}}, m));
  const Side s = m.side_between(VertexId{0}, VertexId{2});
  CHECK(swap_gain(m, s) > 0);
  const SwapStats st = swap_for_quality(m);
  CHECK(st.swaps == 1);
  CHECK(m.has_edge(VertexId{1}, VertexId{3}));
  CHECK(check_topology(m).ok());
  // Swapping back would lower the worst quality.
  const Side back = m.side_between(VertexId{1}, VertexId{3}).valid() ? m.side_between(VertexId{1}, VertexId{3})
                                                                     : m.side_between(VertexId{3}, VertexId{1});
  CHECK(swap_gain(m, back) < 0);
  CHECK(swap_for_quality(m).swaps == 0);
}

TEST_CASE("swap: non-convex quad, hull and constrained edges are refused") {
  // Dart: 0 (0,0), 1 (2,-1), 2 (1,0), 3 (2,1); vertex 2 is reflex, so 1-3 would leave the quad.
  TriangleStore m;
  REQUIRE(build_triangulation({{0, 0}, {2, -1}, {1, 0}, {2, 1}}, {{0, 1, 2}, {0, 2, 3}}, m));
  const Side s = m.side_between(VertexId{0}, VertexId{2});
  CHECK(swap_gain(m, s) < 0);
  CHECK(swap_gain(m, m.side_between(VertexId{0}, VertexId{1})) < 0);  // hull
  TriangleStore r;
  REQUIRE(build_triangulation({{0, 0}, {2, -0.4}, {4, 0}, {2, 0.4}}, {{0, 1, 2}, {0, 2, 3}}, r));
  const Side d = r.side_between(VertexId{0}, VertexId{2});
  r.set_edge_flags(d, kConstrained);
  CHECK(swap_gain(r, d) < 0);
  CHECK(swap_for_quality(r).swaps == 0);
  CHECK(check_topology(r).ok());
}

TEST_CASE("swap: the pass raises the worst rho of a split-up square") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1, false);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  // Splits at off-centre points make poor triangles.
  for (int k = 0; k < 40; ++k) {
    for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
      if (!m.alive(TriId{t})) continue;
      const Side s = side_of(TriId{t}, static_cast<std::uint32_t>(k % 3));
      if (m.constrained(s) || !m.twin[s.value].valid()) continue;
      split_edge(m, s, 0.7 * m.pos(m.org(s)) + 0.3 * m.pos(m.dest(s)));
      break;
    }
  }
  const auto poor = [&] {  // triangles with rho < 0.2
    std::size_t n = 0;
    for (std::uint32_t t = 0; t < m.num_slots(); ++t)
      if (m.alive(TriId{t}))
        n += rho(m.pos(m.vertex(TriId{t}, 0)), m.pos(m.vertex(TriId{t}, 1)), m.pos(m.vertex(TriId{t}, 2))) < 0.2;
    return n;
  };
  const QualityStats before = mesh_quality(m);
  const std::size_t poor_before = poor();
  const SwapStats st = swap_for_quality(m);
  const QualityStats after = mesh_quality(m);
  MESSAGE("swaps " << st.swaps << ", mean rho " << before.mean_rho << " -> " << after.mean_rho << ", rho < 0.2: "
                   << poor_before << " -> " << poor());
  CHECK(st.swaps > 0);
  CHECK(after.min_rho >= before.min_rho);  // the worst triangles here lean on the boundary
  CHECK(after.mean_rho > before.mean_rho);
  CHECK(poor() < poor_before);
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  CHECK(check_constraints(m, edges).ok());
  // No edge is left whose swap would still gain.
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.alive(tri_of(Side{s}))) CHECK(swap_gain(m, Side{s}) <= 1e-6);
}
