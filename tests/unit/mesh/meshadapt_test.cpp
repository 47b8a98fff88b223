// meshadapt in the plane and in the stereographic plane: valid constrained
// mesh, boundary kept, edge lengths within [0.7, 1.4] of the size field,
// quality, holes, graded sizes, determinism, bad sizes.
#include <doctest/doctest.h>

#include <cmath>
#include <span>

#include "mesh/check.h"
#include "mesh/meshadapt.h"
#include "mesh/quality.h"
#include "testing_domains.h"

using namespace sm;

namespace {

void check_adapted(const TriangleStore& m, const std::vector<Edge>& edges) {
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  INFO(check_constraints(m, edges).error);
  REQUIRE(check_constraints(m, edges).ok());
}

double area_of(const TriangleStore& m) {
  double area = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t})) {
      const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
      area += 0.5 * cross(b - a, c - a);
    }
  return area;
}

}  // namespace

TEST_CASE("meshadapt: uniform unit square") {
  const double h = 0.02;
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  const std::uint32_t nb = m.num_vertices();
  const std::vector<Vec2> boundary(m.xy.begin(), m.xy.end());
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  MeshAdaptOptions opt;
  opt.size = h;
  const auto r = mesh_adapt(m, opt);
  REQUIRE(r.ok());
  check_adapted(m, edges);
  // Boundary vertices kept, with their ids and places.
  for (std::uint32_t v = 0; v < nb; ++v) CHECK(m.xy[v] == boundary[v]);
  const QualityStats q = mesh_quality(m, [&](Vec2) { return h; });
  MESSAGE("square h=0.02: " << q.triangles << " triangles, " << r.stats.iterations << " rounds, " << r.stats.splits
                            << " splits, " << r.stats.collapses << " collapses, " << r.stats.swaps << " swaps; min rho "
                            << q.min_rho << ", mean " << q.mean_rho << ", rho>0.9 " << q.share_rho_09
                            << ", len median " << q.len_median << " [" << q.len_p05 << ", " << q.len_p95
                            << "], in [0.7,1.4] " << q.share_len_07_14);
  CHECK(area_of(m) == doctest::Approx(1.0));
  CHECK(q.nodes == m.num_vertices());  // collapsed vertices dropped
  CHECK(q.share_len_07_14 > 0.95);
  CHECK(q.min_rho > 0.3);
  // Deterministic: the same mesh again.
  TriangleStore m2;
  const Loop sq2 = testing::polygon_loop(m2, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  REQUIRE(testing::boundary_mesh(m2, {sq2}));
  REQUIRE(mesh_adapt(m2, opt).ok());
  CHECK(m2.corner == m.corner);
  CHECK(m2.xy == m.xy);
}
