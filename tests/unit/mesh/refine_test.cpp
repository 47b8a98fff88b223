// del2d refinement in the plane: valid constrained Delaunay mesh, boundary
// kept, sizes and quality within bounds, deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "mesh/check.h"
#include "mesh/frontal.h"
#include "mesh/modify/smooth.h"
#include "exact/predicates.h"
#include "mesh/quality.h"
#include "mesh/refine.h"
#include "mesh/refine_queue.h"
#include "testing_domains.h"
#include "testing_sphere.h"

using namespace sm;

namespace {

void check_refined(const TriangleStore& m, const std::vector<Edge>& edges) {
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  REQUIRE(check_constraints(m, edges).ok());
  INFO(check_delaunay(m, PlanarGeometry{&m.xy}, true).error);
  REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
}

// The unit square meshed on its boundary at h and refined by del2d.
TriangleStore refined_square(double h, std::vector<Edge>* edges = nullptr, RefineResult* res = nullptr) {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  REQUIRE(testing::boundary_mesh(m, {sq}, edges));
  RefineOptions opt;
  opt.size = h;
  const RefineResult r = refine_del2d(m, opt);
  REQUIRE(r.ok());
  if (res) *res = r;
  return m;
}

}  // namespace

TEST_CASE("quality: eta and gamma") {
  CHECK(eta({0, 0}, {1, 0}, {0.5, std::sqrt(0.75)}) == doctest::Approx(1));
  CHECK(gamma({0, 0}, {1, 0}, {0.5, std::sqrt(0.75)}) == doctest::Approx(1));
  // Right isosceles: r_in = (2 - sqrt2) / 2, longest edge sqrt2.
  CHECK(gamma({0, 0}, {1, 0}, {0, 1}) ==
        doctest::Approx(2 * std::sqrt(3.0) * (2 - std::sqrt(2.0)) / 2 / std::sqrt(2.0)));
  CHECK(gamma({0, 0}, {1, 0}, {2, 0}) == 0);
  const Vec2 cc = circumcentre({0, 0}, {2, 0}, {0, 2});
  CHECK(cc.x == doctest::Approx(1));
  CHECK(cc.y == doctest::Approx(1));
}

TEST_CASE("refine: the work list serves the largest bucket first, the last queued first inside it") {
  TriangleStore m;
  for (int i = 0; i < 8; ++i) m.add_vertex({double(i), double(i * i)});
  for (std::uint32_t i = 0; i < 6; ++i) m.add_triangle(VertexId{i}, VertexId{i + 1}, VertexId{i + 2});
  detail::RefineQueue q;
  q.grow(m.num_slots());
  q.push(0, 1.0f);
  q.push(1, 4.0f);
  q.push(2, 1.001f);  // same bucket as 1.0 (buckets are 2^(1/32) wide)
  q.push(3, 2.0f);
  q.push(4, 1.5f);
  q.push(5, 3.0f);
  CHECK(q.queued(4));
  q.drop(4);            // re-sized: stale
  m.kill_triangle(TriId{5});  // died in a cavity: stale
  q.push(3, 8.0f);      // re-queued higher: the old entry is stale
  std::vector<std::uint32_t> order;
  for (std::uint32_t t; q.pop(m, t);) order.push_back(t);
  CHECK(order == std::vector<std::uint32_t>{3, 1, 2, 0});
  CHECK(q.pops == 7);
  CHECK(q.stale == 3);
  CHECK_FALSE(q.queued(0));
  // Tiny and huge priorities have buckets too.
  q.push(0, 1e-30f);
  q.push(1, 3e38f);
  std::uint32_t t = 9;
  REQUIRE(q.pop(m, t));
  CHECK(t == 1);
  REQUIRE(q.pop(m, t));
  CHECK(t == 0);
  CHECK_FALSE(q.pop(m, t));
}

TEST_CASE("refine: uniform unit square") {
  const double h = 0.02;
  std::vector<Edge> edges;
  RefineResult r;
  const TriangleStore m = refined_square(h, &edges, &r);
  check_refined(m, edges);
  const QualityStats q = mesh_quality(m, [&](Vec2) { return h; });
  MESSAGE("square h=0.02: " << q.triangles << " triangles, min rho " << q.min_rho << ", mean " << q.mean_rho
                            << ", rho>0.9 " << q.share_rho_09 << ", len median " << q.len_median << " [" << q.len_p05
                            << ", " << q.len_p95 << "], in [0.7,1.4] " << q.share_len_07_14 << ", rejected "
                            << r.stats.rejected);
  double area = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t})) {
      const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
      area += 0.5 * cross(b - a, c - a);
      // Every triangle below the radius bound.
      CHECK(circumradius(a, b, c) <= RefineOptions{}.radius_limit * h * (1 + 1e-9));
    }
  CHECK(area == doctest::Approx(1.0));
  CHECK(q.min_rho > 0.4);
  CHECK(q.share_rho_09 > 0.6);  // 62% before smoothing; Gmsh del2d (with one smoothing pass) 84%
  CHECK(q.share_len_07_14 > 0.9);
  // Deterministic: the same mesh again.
  const TriangleStore m2 = refined_square(h);
  CHECK(m2.corner == m.corner);
  CHECK(m2.xy == m.xy);
}

TEST_CASE("refine: a run long enough to be renumbered along the curve stays constrained Delaunay") {
  // h = 0.006: ~64k triangles, so the mesh is sorted spatially once on the
  // way (from 32k triangles); boundary vertices keep their ids.
  const double h = 0.006;
  TriangleStore boundary_only;
  testing::polygon_loop(boundary_only, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  std::vector<Edge> edges;
  const TriangleStore m = refined_square(h, &edges);
  CHECK(m.num_triangles() > 40000);
  check_refined(m, edges);
  for (std::size_t v = 0; v < boundary_only.xy.size(); ++v) CHECK(m.xy[v] == boundary_only.xy[v]);
  const QualityStats q = mesh_quality(m, [&](Vec2) { return h; });
  CHECK(q.min_rho > 0.4);
  CHECK(q.share_len_07_14 > 0.9);
  // Deterministic through the renumbering.
  const TriangleStore m2 = refined_square(h);
  CHECK(m2.corner == m.corner);
  CHECK(m2.xy == m.xy);
}

TEST_CASE("refine: square with circular holes and a graded size") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.01, false);
  const Loop h1 = testing::circle_loop(m, {0.5, 0.5}, 0.2, 0.01, true);
  const Loop h2 = testing::circle_loop(m, {1.4, 0.45}, 0.25, 0.01, true);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq, h1, h2}, &edges));
  RefineOptions opt;
  const auto size = [](Vec2 p) { return 0.01 + 0.05 * std::min(1.0, std::fabs(p.y - 0.5)); };
  std::size_t calls = 0, points = 0;
  opt.size_at = [&](std::span<const Vec2> pts, std::span<double> h) {
    ++calls, points += pts.size();
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = size(pts[i]);
  };
  const auto r = refine_del2d(m, opt);
  REQUIRE(r.ok());
  check_refined(m, edges);
  CHECK(points > 4 * calls);  // batches, not one call per point
  const QualityStats q = mesh_quality(m, size);
  MESSAGE("holes, graded: " << q.triangles << " triangles, min rho " << q.min_rho << ", rho>0.9 " << q.share_rho_09
                            << ", len in [0.7,1.4] " << q.share_len_07_14);
  CHECK(q.min_rho > 0.2);
  CHECK(r.stats.inserted > 1000);
  // No vertex inside a hole.
  for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
    CHECK(norm(m.xy[v] - Vec2{0.5, 0.5}) >= 0.2 * (1 - 1e-12) * std::cos(M_PI / std::ceil(2 * M_PI * 0.2 / 0.01)));
  }
}

TEST_CASE("refine: a bad size is an error, not a hang") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, false);
  REQUIRE(testing::boundary_mesh(m, {sq}));
  RefineOptions opt;
  opt.size_at = [](std::span<const Vec2> p, std::span<double> h) {
    for (std::size_t i = 0; i < p.size(); ++i) h[i] = p[i].x > 0.5 ? 0.0 : 0.1;
  };
  CHECK_FALSE(refine_del2d(m, opt).ok());
  opt.size_at = [](std::span<const Vec2>, std::span<double> h) { std::fill(h.begin(), h.end(), std::nan("")); };
  CHECK_FALSE(refine_del2d(m, opt).ok());
  opt.size_at = nullptr;
  opt.size = -1;
  CHECK_FALSE(refine_del2d(m, opt).ok());
  opt.size = 0.1;
  opt.radius_limit = 0;  // no triangle could ever meet it
  CHECK(refine_del2d(m, opt).error.find("radius limit") != std::string::npos);
  opt.radius_limit = 0.7;
  opt.max_vertices = 60;
  const RefineResult r = refine_del2d(m, opt);
  CHECK(r.error.find("vertex limit") != std::string::npos);
  CHECK(m.num_vertices() == 60);
  CHECK(check_topology(m).ok());
}

TEST_CASE("refine: a spherical cap meshed in the stereographic plane (paper section 3.1)") {
  // Unit sphere projected from the South Pole: the plane size is
  // delta_u = delta / lambda(u) (testing_sphere.h).
  const double delta = 0.04;
  TriangleStore m;
  const Loop cap = testing::cap_loop(m, delta);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {cap}, &edges));
  RefineOptions opt;
  opt.size_at = testing::stereo_size(delta);
  REQUIRE(refine_del2d(m, opt).ok());
  smooth_laplacian(m, 1);
  check_refined(m, edges);
  // Edge lengths measured on the sphere (great-circle arcs).
  const testing::SphereStats st = testing::sphere_stats(m, delta);
  MESSAGE("cap: " << m.num_triangles() << " triangles, " << 100.0 * st.in_07_14
                  << "% of edges within [0.7, 1.4] delta on the sphere");
  CHECK(st.in_07_14 > 0.95);
  // Triangles fill the cap's area (2 pi (1 - cos 60) = pi) at about the
  // equilateral density of the target size.
  const double expected = testing::cap_triangles_expected(delta);
  CHECK(m.num_triangles() > 0.9 * expected);
  CHECK(m.num_triangles() < 1.5 * expected);
}

TEST_CASE("refine: a triangle flat to double precision never sends a point at infinity to the size") {
  // Counter-clockwise by the exact predicates, but cross(b - a, c - a) rounds to 0, so the
  // constructed circumcentre is not finite (two close islands met this in front2d: "mesh
  // size must be positive and finite (got inf at (inf, inf))"). The size function, like
  // mesh2d's, is not finite there.
  const Vec2 a{0.30000000000000004, 0.2}, b{0.5550690257394217, 0.695435087091941},
      c{0.4198045539324276, 0.4327032043167829};
  REQUIRE(orient2d(a, b, c) == Sign::Positive);
  const Vec2 cc = circumcentre(a, b, c);
  REQUIRE_FALSE((std::isfinite(cc.x) && std::isfinite(cc.y)));
  for (const bool frontal : {false, true}) {
    CAPTURE(frontal);
    TriangleStore m;
    Loop l;
    for (Vec2 p : {a, b, c}) l.v.push_back(m.add_vertex(p));
    REQUIRE(testing::boundary_mesh(m, {l}));
    REQUIRE(m.num_triangles() == 1);
    RefineOptions opt;
    opt.size_at = [](std::span<const Vec2> p, std::span<double> h) {
      for (std::size_t i = 0; i < p.size(); ++i)
        h[i] = std::isfinite(p[i].x) && std::isfinite(p[i].y) ? 0.05 : std::numeric_limits<double>::infinity();
    };
    const RefineResult r = frontal ? RefineResult(refine_front2d(m, opt)) : refine_del2d(m, opt);
    INFO(r.error);
    CHECK(r.ok());
    for (Vec2 p : m.xy) CHECK((std::isfinite(p.x) && std::isfinite(p.y)));
    CHECK(check_topology(m).ok());
  }
}
