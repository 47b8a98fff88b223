// meshadapt in the plane and in the stereographic plane: valid constrained
// mesh, boundary kept, edge lengths within [0.7, 1.4] of the size field,
// quality, holes, graded sizes, determinism, bad sizes.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <span>

#include "mesh/check.h"
#include "mesh/meshadapt.h"
#include "mesh/quality.h"
#include "testing_coast.h"
#include "testing_domains.h"
#include "testing_sphere.h"

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

namespace {

// A closed polygon whose sides are cut following the size field (steps of
// the local size, then evened out per side), appended to m.
Loop graded_polygon(TriangleStore& m, const std::vector<Vec2>& corners, const std::function<double(Vec2)>& size,
                    bool hole) {
  Loop l;
  l.hole = hole;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const double len = norm(b - a);
    std::vector<double> t{0};
    while (t.back() < 1) t.push_back(t.back() + size(a + t.back() * (b - a)) / len);
    const double scale = 1 / t.back();  // last step lands on b
    for (std::size_t k = 0; k + 1 < t.size(); ++k) l.v.push_back(m.add_vertex(a + (t[k] * scale) * (b - a)));
  }
  return l;
}

Loop graded_circle(TriangleStore& m, Vec2 c, double r, const std::function<double(Vec2)>& size) {
  Loop l;
  l.hole = true;
  std::vector<double> t{0};
  while (t.back() < 2 * M_PI) t.push_back(t.back() + size(c + r * Vec2{std::cos(t.back()), std::sin(t.back())}) / r);
  const double scale = 2 * M_PI / t.back();
  for (std::size_t k = 0; k + 1 < t.size(); ++k)
    l.v.push_back(m.add_vertex(c + r * Vec2{std::cos(t[k] * scale), std::sin(t[k] * scale)}));
  return l;
}

}  // namespace

TEST_CASE("meshadapt: graded size round two holes") {
  const auto size = [](Vec2 p) { return 0.01 + 0.05 * std::min(1.0, std::fabs(p.y - 0.5)); };
  TriangleStore m;
  const Loop sq = graded_polygon(m, {{0, 0}, {2, 0}, {2, 1}, {0, 1}}, size, false);
  const Loop h1 = graded_circle(m, {0.5, 0.5}, 0.2, size);
  const Loop h2 = graded_circle(m, {1.4, 0.45}, 0.25, size);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq, h1, h2}, &edges));
  const std::uint32_t nb = m.num_vertices();
  MeshAdaptOptions opt;
  std::size_t calls = 0, points = 0;
  opt.size_at = [&](std::span<const Vec2> pts, std::span<double> h) {
    ++calls, points += pts.size();
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = size(pts[i]);
  };
  const auto r = mesh_adapt(m, opt);
  REQUIRE(r.ok());
  check_adapted(m, edges);
  CHECK(points > 4 * calls);  // batches, not one call per point
  const QualityStats q = mesh_quality(m, size);
  MESSAGE("holes, graded: " << q.triangles << " triangles, " << r.stats.iterations << " rounds, " << r.stats.collapses
                            << " collapses; min rho " << q.min_rho << ", rho>0.9 " << q.share_rho_09
                            << ", len median " << q.len_median << " [" << q.len_p05 << ", " << q.len_p95
                            << "], in [0.7,1.4] " << q.share_len_07_14);
  CHECK(q.share_len_07_14 > 0.95);
  CHECK(q.min_rho > 0.3);
  CHECK(q.share_rho_09 > 0.8);
  CHECK(area_of(m) == doctest::Approx(2 - M_PI * (0.04 + 0.0625)).epsilon(0.01));
  // Graded: edges near y = 0.5 are much shorter than edges near y = 0 or 1.
  double near = 0, far = 0;
  std::size_t n_near = 0, n_far = 0;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    const Vec2 a = m.pos(m.org(Side{s})), b = m.pos(m.dest(Side{s}));
    const double y = 0.5 * (a.y + b.y);
    if (std::fabs(y - 0.5) < 0.05) near += norm(b - a), ++n_near;
    if (std::fabs(y - 0.5) > 0.45) far += norm(b - a), ++n_far;
  }
  REQUIRE(n_near > 0);
  REQUIRE(n_far > 0);
  CHECK(far / n_far > 2.5 * (near / n_near));
  // No vertex inside a hole; boundary vertices untouched and first.
  for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
    CHECK(norm(m.xy[v] - Vec2{0.5, 0.5}) > 0.19);
    CHECK(norm(m.xy[v] - Vec2{1.4, 0.45}) > 0.24);
  }
  for (const Loop* l : {&sq, &h1, &h2})
    for (VertexId v : l->v) CHECK(v.value < nb);
}

TEST_CASE("meshadapt: the checkers hold after every pass") {
  const auto size = [](Vec2 p) { return 0.03 + 0.05 * p.x; };
  TriangleStore m;
  const Loop sq = graded_polygon(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, size, false);
  const Loop hole = graded_circle(m, {0.45, 0.5}, 0.2, size);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq, hole}, &edges));
  MeshAdaptOptions opt;
  opt.size_at = [&](std::span<const Vec2> pts, std::span<double> h) {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = size(pts[i]);
  };
  std::map<std::string, int> passes;
  opt.after_pass = [&](const TriangleStore& t, const char* pass) {
    ++passes[pass];
    const CheckResult topo = check_topology(t);
    INFO(pass, ": ", topo.error);
    REQUIRE(topo.ok());
    const CheckResult cons = check_constraints(t, edges);
    INFO(pass, ": ", cons.error);
    REQUIRE(cons.ok());
  };
  const auto r = mesh_adapt(m, opt);
  REQUIRE(r.ok());
  CHECK(passes["split"] >= 5);
  CHECK(passes["collapse"] == passes["split"]);
  CHECK(passes["swap"] == passes["split"] + 2);
  CHECK(passes["smooth"] == passes["split"] + 1);
  CHECK(r.stats.collapses > 0);
  CHECK(mesh_quality(m, size).share_len_07_14 > 0.95);
}

TEST_CASE("meshadapt: a spherical cap in the stereographic plane (paper section 3.1)") {
  // Unit sphere projected from the South Pole: the plane size is
  // delta_u = delta / lambda(u) (testing_sphere.h).
  const double delta = 0.05;
  TriangleStore m;
  const Loop cap = testing::cap_loop(m, delta);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {cap}, &edges));
  MeshAdaptOptions opt;
  opt.size_at = testing::stereo_size(delta);
  const auto r = mesh_adapt(m, opt);
  REQUIRE(r.ok());
  check_adapted(m, edges);
  // Arcs and the flat triangles through the three points, on the sphere.
  const testing::SphereStats st = testing::sphere_stats(m, delta);
  MESSAGE("cap: " << m.num_triangles() << " triangles, " << 100.0 * st.in_07_14
                  << "% of edges within [0.7, 1.4] delta, " << 100.0 * st.rho_09 << "% rho > 0.9 on the sphere");
  CHECK(st.in_07_14 > 0.95);
  CHECK(st.rho_09 > 0.8);
  const double expected = testing::cap_triangles_expected(delta);
  CHECK(m.num_triangles() > 0.9 * expected);
  CHECK(m.num_triangles() < 1.3 * expected);
}

TEST_CASE("meshadapt: coarsening an earlier mesh collapses its vertices") {
  // A fine mesh made by meshadapt, re-adapted to twice the size with its
  // interior vertices free: collapses do the work.
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.04, false);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  MeshAdaptOptions fine;
  fine.size = 0.02;
  fine.split_constrained = true;  // straight sides: their halves stay on them
  REQUIRE(mesh_adapt(m, fine).ok());
  const std::uint32_t before = m.num_triangles();
  // The boundary now has the split points too.
  std::vector<Edge> boundary;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.alive(tri_of(Side{s})) && m.constrained(Side{s})) boundary.push_back({m.org(Side{s}), m.dest(Side{s})});
  CHECK(boundary.size() == 200);
  MeshAdaptOptions coarse;
  coarse.size = 0.04;
  coarse.move_input_vertices = true;
  const auto r = mesh_adapt(m, coarse);
  REQUIRE(r.ok());
  for (auto& [a, b] : boundary) a = VertexId{r.vertex_map[a.value]}, b = VertexId{r.vertex_map[b.value]};
  check_adapted(m, boundary);
  const QualityStats q = mesh_quality(m, [](Vec2) { return 0.04; });  // boundary edges stay at 0.02
  MESSAGE("coarsened: " << before << " -> " << q.triangles << " triangles, " << r.stats.collapses << " collapses, "
                        << r.stats.splits << " splits; len in [0.7,1.4] " << q.share_len_07_14 << ", min rho "
                        << q.min_rho);
  CHECK(r.stats.collapses > 500);
  CHECK(q.triangles < before / 2);
  CHECK(q.nodes == m.num_vertices());
  CHECK(area_of(m) == doctest::Approx(1.0));
  CHECK(q.min_rho > 0.2);
  CHECK(q.len_median > 0.85);
}

TEST_CASE("meshadapt: embedded points stay; bad sizes are errors, not hangs") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1, false);
  const VertexId p = m.add_vertex({0.31, 0.47});  // like Point{..} In Surface{..}
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  REQUIRE(m.out_side[p.value].valid());
  MeshAdaptOptions opt;
  opt.size = 0.1;
  REQUIRE(mesh_adapt(m, opt).ok());
  check_adapted(m, edges);
  CHECK(m.xy[p.value] == Vec2{0.31, 0.47});
  CHECK(m.out_side[p.value].valid());

  TriangleStore b;
  const Loop sq2 = testing::polygon_loop(b, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, false);
  REQUIRE(testing::boundary_mesh(b, {sq2}));
  MeshAdaptOptions bad;
  bad.size_at = [](std::span<const Vec2> q, std::span<double> h) {
    for (std::size_t i = 0; i < q.size(); ++i) h[i] = q[i].x > 0.5 ? 0.0 : 0.1;
  };
  const auto r = mesh_adapt(b, bad);
  CHECK_FALSE(r.ok());
  CHECK(r.error.find("positive") != std::string::npos);
  bad.size_at = [](std::span<const Vec2>, std::span<double> h) { std::fill(h.begin(), h.end(), std::nan("")); };
  CHECK_FALSE(mesh_adapt(b, bad).ok());
  bad.size_at = nullptr;
  bad.size = -1;
  CHECK_FALSE(mesh_adapt(b, bad).ok());
  MeshAdaptOptions tiny;
  tiny.size = 1e-4;
  tiny.max_vertices = 2000;
  const auto t = mesh_adapt(b, tiny);
  CHECK_FALSE(t.ok());
  CHECK(t.error.find("vertex limit") != std::string::npos);
  CHECK(check_topology(b).ok());
}

TEST_CASE("meshadapt: the world ocean from GSHHG crude shorelines on the sphere (real data)") {
  // Shorelines resampled every 150 km in the stereographic plane from the
  // South Pole (Antarctica's ring, round the pole, is the outer loop), the
  // ocean meshed at delta = 150 km: delta_u = delta / lambda(u).
  const double step_km = 150, delta = step_km / 6371.0;
  const auto rings = testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(rings.size() > 100);
  std::vector<testing::RingCurve> curves;
  for (const auto& r : rings) curves.emplace_back(r);
  BoundaryProblem p = testing::coast_problem(curves, step_km);
  const BoundaryResult br = recover_boundary(p, [&](std::uint32_t c, double t) { return curves[c].at(t); }, {});
  INFO(br.error.message);
  REQUIRE(br.ok());
  const std::vector<Loop> loops = testing::ocean_loops(p, rings);
  TriangleStore m = br.mesh;
  REQUIRE(remove_outside(m, PlanarGeometry{&m.xy}, loops).ok());
  // The coast edges left (rings inside removed regions went with them).
  std::vector<Edge> coast;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.alive(tri_of(Side{s})) && m.constrained(Side{s})) coast.push_back({m.org(Side{s}), m.dest(Side{s})});
  REQUIRE(coast.size() > 1000);
  const std::uint32_t nb = m.num_vertices();
  MeshAdaptOptions opt;
  opt.size_at = testing::stereo_size(delta);
  const auto r = mesh_adapt(m, opt);
  REQUIRE(r.ok());
  check_adapted(m, coast);
  // Edges with a free end (the coast is as the resampling made it: small
  // islands are triangles far below delta).
  std::size_t in = 0, total = 0;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    const Side o = m.twin[s];
    if (o.valid() && o.value < s) continue;
    if (m.org(Side{s}).value < nb && m.dest(Side{s}).value < nb) continue;
    const Vec3 a = testing::unit_on_sphere(m.pos(m.org(Side{s}))), b = testing::unit_on_sphere(m.pos(m.dest(Side{s})));
    const double arc = std::atan2(norm(cross(a, b)), dot(a, b));
    in += arc >= 0.7 * delta && arc <= 1.4 * delta;
    ++total;
  }
  const QualityStats q = mesh_quality(m);
  std::size_t open_sea = 0, good = 0;  // triangles away from the coast
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    const VertexId a = m.vertex(TriId{t}, 0), b = m.vertex(TriId{t}, 1), c = m.vertex(TriId{t}, 2);
    if (a.value < nb || b.value < nb || c.value < nb) continue;
    ++open_sea;
    good += rho(m.pos(a), m.pos(b), m.pos(c)) > 0.9;
  }
  MESSAGE("world ocean at 150 km: " << nb << " coast points, " << m.num_triangles() << " triangles, "
                                    << r.stats.iterations << " rounds; " << 100.0 * in / total
                                    << "% of edges with a free end within [0.7, 1.4] delta; rho>0.9 " << q.share_rho_09
                                    << " (away from the coast " << double(good) / open_sea << ")");
  CHECK(double(in) / total > 0.95);
  CHECK(q.share_rho_09 > 0.7);
  CHECK(double(good) / open_sea > 0.85);
  // The ocean is about 71% of the sphere: 0.71 * 4 pi / (sqrt3/4 delta^2) equilateral triangles.
  const double expected = 0.71 * 4 * M_PI / (std::sqrt(3.0) / 4 * delta * delta);
  CHECK(m.num_triangles() > 0.8 * expected);
  CHECK(m.num_triangles() < 1.3 * expected);
}
