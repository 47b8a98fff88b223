// front2d (frontal-Delaunay, Rebay) in the plane and in the stereographic
// plane: valid constrained Delaunay mesh, boundary kept, sizes and quality
// within bounds, holes, graded sizes, deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "mesh/check.h"
#include "mesh/frontal.h"
#include "mesh/modify/smooth.h"
#include "mesh/quality.h"
#include "mesh/refine.h"
#include "testing_coast.h"
#include "testing_domains.h"
#include "testing_sphere.h"

using namespace sm;

namespace {

void check_valid(const TriangleStore& m, const std::vector<Edge>& edges) {
  const CheckResult topo = check_topology(m), cons = check_constraints(m, edges),
                    del = check_delaunay(m, PlanarGeometry{&m.xy}, true);
  INFO(topo.error, cons.error, del.error);
  REQUIRE(topo.ok());
  REQUIRE(cons.ok());
  REQUIRE(del.ok());
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


// A closed curve x(s), s in [0, 1), cut into pieces of about the local size:
// equal steps of the integral of |x'| / size (the 1D mesher's rule).
template <class Curve, class Size>
Loop graded_loop(TriangleStore& m, Curve x, Size size, bool hole) {
  const int fine = 20000;
  std::vector<double> acc(fine + 1, 0.0);
  for (int i = 0; i < fine; ++i) {
    const Vec2 a = x(double(i) / fine), b = x(double(i + 1) / fine);
    acc[i + 1] = acc[i] + norm(b - a) / size(0.5 * (a + b));
  }
  const int n = std::max(3, static_cast<int>(std::lround(acc[fine])));
  Loop l;
  l.hole = hole;
  for (int k = 0, i = 0; k < n; ++k) {
    const double target = acc[fine] * k / n;
    while (acc[i + 1] < target) ++i;
    const double f = (target - acc[i]) / (acc[i + 1] - acc[i]);
    l.v.push_back(m.add_vertex(x((i + f) / fine)));
  }
  return l;
}

}  // namespace

TEST_CASE("front2d: uniform unit square") {
  const double h = 0.02;
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  RefineOptions opt;
  opt.size = h;
  const FrontalResult r = refine_front2d(m, opt);
  REQUIRE(r.ok());
  check_valid(m, edges);
  const QualityStats q = mesh_quality(m, [&](Vec2) { return h; });
  MESSAGE("front2d square h=0.02: " << q.triangles << " triangles, min rho " << q.min_rho << ", mean " << q.mean_rho
                                    << ", rho>0.9 " << q.share_rho_09 << ", len median " << q.len_median << " ["
                                    << q.len_p05 << ", " << q.len_p95 << "], in [0.7,1.4] " << q.share_len_07_14
                                    << "; frontal " << r.frontal_points << ", circumcentre " << r.circumcentre_fallbacks
                                    << ", given up " << r.given_up);
  CHECK(area_of(m) == doctest::Approx(1.0));
  // Every triangle is resolved unless it was given up.
  std::uint64_t over = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t})) {
      const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
      over += circumradius(a, b, c) > opt.radius_limit * h * (1 + 1e-9);
    }
  CHECK(over <= r.given_up);
  CHECK(r.frontal_points > 0.9 * r.stats.inserted);
  CHECK(q.share_rho_09 > 0.95);
  CHECK(q.min_rho > 0.6);  // 0.70: where two fronts meet
  CHECK(q.share_len_07_14 > 0.95);
  smooth_laplacian(m, 1);
  check_valid(m, edges);
  const QualityStats qs = mesh_quality(m, [&](Vec2) { return h; });
  MESSAGE("after one smoothing pass: min rho " << qs.min_rho << ", rho>0.9 " << qs.share_rho_09);
  CHECK(qs.share_rho_09 > 0.985);
  CHECK(qs.min_rho > 0.7);
  // Deterministic: the same triangles again.
  TriangleStore m2;
  const Loop sq2 = testing::polygon_loop(m2, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  REQUIRE(testing::boundary_mesh(m2, {sq2}));
  REQUIRE(refine_front2d(m2, opt).ok());
  smooth_laplacian(m2, 1);
  CHECK(m2.corner == m.corner);
  CHECK(m2.xy == m.xy);
}

TEST_CASE("front2d: square with circular holes, an embedded polyline and a graded size") {
  const auto size = [](Vec2 p) { return 0.01 + 0.05 * std::min(1.0, std::fabs(p.y - 0.5)); };
  TriangleStore m;
  // Boundaries discretised at the field's size, as the 1D mesher does.
  const auto rect = [](double s) {
    const double u = 6 * s;  // perimeter 6: (0,0) -> (2,0) -> (2,1) -> (0,1)
    if (u < 2) return Vec2{u, 0};
    if (u < 3) return Vec2{2, u - 2};
    if (u < 5) return Vec2{5 - u, 1};
    return Vec2{0, 6 - u};
  };
  const auto circle = [](Vec2 c, double r) {
    return [c, r](double s) { return Vec2{c.x + r * std::cos(2 * M_PI * s), c.y + r * std::sin(2 * M_PI * s)}; };
  };
  const Loop sq = graded_loop(m, rect, size, false);
  const Loop h1 = graded_loop(m, circle({0.5, 0.5}, 0.2), size, true);
  const Loop h2 = graded_loop(m, circle({1.4, 0.45}, 0.25), size, true);
  // An embedded open polyline (Curve In Surface): constrained, not a loop.
  std::vector<VertexId> line;
  for (int k = 0; k <= 30; ++k)
    line.push_back(m.add_vertex({0.85 + 0.01 * k * std::cos(0.3), 0.2 + 0.01 * k * std::sin(0.3)}));
  std::vector<Edge> edges;
  REQUIRE(delaunay(m).ok());
  for (const Loop* l : {&sq, &h1, &h2})
    for (std::size_t k = 0; k < l->v.size(); ++k) edges.push_back({l->v[k], l->v[(k + 1) % l->v.size()]});
  for (std::size_t k = 0; k + 1 < line.size(); ++k) edges.push_back({line[k], line[k + 1]});
  const PlanarGeometry g{&m.xy};
  REQUIRE(recover_edges(m, g, edges).clean());
  REQUIRE(remove_outside(m, g, {sq, h1, h2}).ok());
  RefineOptions opt;
  std::size_t calls = 0, points = 0;
  opt.size_at = [&](std::span<const Vec2> pts, std::span<double> h) {
    ++calls, points += pts.size();
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = size(pts[i]);
  };
  const FrontalResult r = refine_front2d(m, opt);
  REQUIRE(r.ok());
  check_valid(m, edges);
  CHECK(points > 4 * calls);  // batches, not one call per point
  const QualityStats q = mesh_quality(m, size);
  MESSAGE("front2d holes, graded: " << q.triangles << " triangles, min rho " << q.min_rho << ", rho>0.9 "
                                    << q.share_rho_09 << ", len median " << q.len_median << " [" << q.len_p05 << ", "
                                    << q.len_p95 << "], in [0.7,1.4] " << q.share_len_07_14 << "; circumcentre "
                                    << r.circumcentre_fallbacks << ", given up " << r.given_up);
  CHECK(r.stats.inserted > 1000);
  CHECK(q.min_rho > 0.4);
  CHECK(q.share_rho_09 > 0.86);
  CHECK(q.share_len_07_14 > 0.98);
  const double holes = M_PI * (0.2 * 0.2 + 0.25 * 0.25);
  CHECK(area_of(m) == doctest::Approx(2.0 - holes).epsilon(2e-3));  // holes are inscribed polygons
  // No vertex inside a hole (the inscribed polygons' edges are at most 0.03 long).
  const double sag = 0.03 * 0.03 / 8 / 0.2;
  for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
    CHECK(norm(m.xy[v] - Vec2{0.5, 0.5}) >= 0.2 - sag);
    CHECK(norm(m.xy[v] - Vec2{1.4, 0.45}) >= 0.25 - sag);
  }
}

TEST_CASE("front2d: bad sizes and limits are errors, not hangs") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, false);
  REQUIRE(testing::boundary_mesh(m, {sq}));
  RefineOptions opt;
  opt.size_at = [](std::span<const Vec2> p, std::span<double> h) {
    for (std::size_t i = 0; i < p.size(); ++i) h[i] = p[i].x > 0.5 ? 0.0 : 0.1;
  };
  FrontalResult r = refine_front2d(m, opt);
  CHECK_FALSE(r.ok());
  CHECK(r.error.find("positive") != std::string::npos);
  MESSAGE(r.error);
  CHECK(r.error.find(" at (0.") != std::string::npos);  // located: a point with x > 0.5
  CHECK(check_topology(m).ok());
  opt.size_at = [](std::span<const Vec2>, std::span<double> h) { std::fill(h.begin(), h.end(), std::nan("")); };
  CHECK_FALSE(refine_front2d(m, opt).ok());
  opt.size_at = nullptr;
  opt.size = -1;
  CHECK_FALSE(refine_front2d(m, opt).ok());
  opt.size = 0.001;
  opt.max_vertices = 500;
  r = refine_front2d(m, opt);
  CHECK_FALSE(r.ok());
  CHECK(r.error.find("vertex limit") != std::string::npos);
  CHECK(m.num_vertices() == 500);
  CHECK(check_topology(m).ok());
}

TEST_CASE("front2d: a spherical cap meshed in the stereographic plane (paper section 3.1)") {
  // Unit sphere projected from the South Pole: u = (x, y) / (1 + z); a length
  // on the sphere is lambda(u) = 2 / (1 + |u|^2) times the length in the
  // plane, so the plane size is delta_u = delta / lambda (conformal map).
  const double delta = 0.04;
  TriangleStore m;
  const Loop cap = testing::cap_loop(m, delta);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {cap}, &edges));
  RefineOptions opt;
  opt.size_at = testing::stereo_size(delta);
  REQUIRE(refine_front2d(m, opt).ok());
  check_valid(m, edges);
  const testing::SphereStats st = testing::sphere_stats(m, delta);
  MESSAGE("front2d cap: " << m.num_triangles() << " triangles, " << 100 * st.in_07_14
                          << "% of edges within [0.7, 1.4] delta on the sphere, " << 100 * st.rho_09
                          << "% rho > 0.9 on the sphere");
  CHECK(st.in_07_14 > 0.99);
  CHECK(st.rho_09 > 0.91);
  const double expected = testing::cap_triangles_expected(delta);
  CHECK(m.num_triangles() > 0.9 * expected);
  CHECK(m.num_triangles() < 1.3 * expected);
}

TEST_CASE("front2d: the world ocean from GSHHG crude shorelines at 150 km in the stereographic plane") {
  // Real data: every ring resampled at 150 km, recovered (paper section
  // 3.2), Antarctica's ring (round the projection pole) the outer loop,
  // every other ring an island; uniform 150 km on the sphere.
  const auto rings = testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(rings.size() > 100);
  std::vector<testing::RingCurve> curves;
  for (const auto& r : rings) curves.emplace_back(r);
  const double step_km = 150;
  BoundaryProblem p = testing::coast_problem(curves, step_km);
  BoundaryOptions bopt;
  bopt.tolerance = 1e-9;
  const BoundaryResult br = recover_boundary(p, [&](std::uint32_t c, double t) { return curves[c].at(t); }, bopt);
  INFO(br.error.message);
  REQUIRE(br.ok());
  const std::vector<Loop> loops = testing::ocean_loops(p, rings);
  TriangleStore m = br.mesh;
  REQUIRE(remove_outside(m, PlanarGeometry{&m.xy}, loops).ok());
  // Rings inside land (lakes, GSHHG level 2) went with the land: keep the
  // coastline edges that bound the ocean.
  std::vector<Edge> edges;
  for (const Edge& e : br.edges)
    if (m.has_edge(e.first, e.second)) edges.push_back(e);
  MESSAGE((br.edges.size() - edges.size()) << " of " << br.edges.size() << " recovered edges lie inside land");
  const double delta = step_km / 6371.0;  // unit sphere
  RefineOptions opt;
  opt.size_at = testing::stereo_size(delta);
  TriangleStore m_del = m;
  const FrontalResult r = refine_front2d(m, opt);
  INFO(r.error);
  REQUIRE(r.ok());
  check_valid(m, edges);
  const testing::SphereStats st = testing::sphere_stats(m, delta);
  const double ocean_km2 = st.area * 6371.0 * 6371.0;
  // del2d on the same boundary mesh, for comparison.
  REQUIRE(refine_del2d(m_del, opt).ok());
  const testing::SphereStats sd = testing::sphere_stats(m_del, delta);
  MESSAGE("world ocean (GSHHG crude, 150 km), " << loops.size() << " loops: front2d " << m.num_triangles()
          << " triangles, " << 100 * st.in_07_14 << "% of arcs in [0.7, 1.4] delta, " << 100 * st.rho_09
          << "% rho > 0.9 on the sphere, ocean " << ocean_km2 / 1e6 << " M km2, " << r.given_up
          << " triangles given up; del2d " << m_del.num_triangles() << " triangles, " << 100 * sd.in_07_14 << "%, "
          << 100 * sd.rho_09 << "%");
  // The world ocean covers about 361 M km2 (71% of the sphere).
  CHECK(ocean_km2 > 330e6);
  CHECK(ocean_km2 < 390e6);
  // Below the square's figures: the crude rings' tiny islands (3 points)
  // and straits narrower than 150 km force short edges and flat triangles
  // (those are the given-up ones: every candidate point lies beyond the coast).
  CHECK(st.in_07_14 > 0.88);
  CHECK(st.rho_09 > 0.74);
  CHECK(st.rho_09 > sd.rho_09 + 0.1);
  CHECK(r.given_up < m.num_triangles() / 200);
}

TEST_CASE("front2d: a sharp wedge and a narrow notch terminate with a bounded number of points") {
  // Small input angles and passages narrower than h are where refinement
  // can cascade; the mesh must stay near the equilateral count for the area.
  const double h = 0.02, a5 = 5 * M_PI / 180;
  const std::vector<std::vector<Vec2>> shapes = {
      {{0, 0}, {1, 0}, {1, std::tan(a5)}},                                    // 5 degree wedge
      {{0, 0}, {1, 0}, {1, 1}, {0.505, 1}, {0.5, 0.1}, {0.495, 1}, {0, 1}}};  // notch 0.01 wide at the top
  for (const auto& shape : shapes) {
    TriangleStore m;
    const Loop outer = testing::polygon_loop(m, shape, h, false);
    std::vector<Edge> edges;
    REQUIRE(testing::boundary_mesh(m, {outer}, &edges));
    RefineOptions opt;
    opt.size = h;
    const FrontalResult r = refine_front2d(m, opt);
    REQUIRE(r.ok());
    check_valid(m, edges);
    const double equilateral = area_of(m) / (std::sqrt(3.0) / 4 * h * h);
    MESSAGE(shape.size() << " corners: " << m.num_triangles() << " triangles (area / equilateral " << equilateral
                         << "), circumcentre " << r.circumcentre_fallbacks << ", given up " << r.given_up);
    CHECK(m.num_triangles() < 1.5 * equilateral + 200);
  }
}
