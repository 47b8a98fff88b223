// mesh/transfinite_surface: structured grids on a unit square (node positions, element
// counts, the arrangements' diagonals, recombined quadrangles), a 3-sided face, unequal
// opposite sides refused, and the 2D driver meshing a transfinite Plane Surface.
#include "mesh/transfinite_surface.h"

#include <doctest/doctest.h>

#include <set>
#include <utility>
#include <vector>

#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"

namespace transfinite_surface_testing {

// The unit square's boundary with nx edges along x and ny along y, counter-clockwise
// from (0, 0); corners at 0, nx, nx + ny, 2 nx + ny.
sm::TransfiniteBoundary square(int nx, int ny) {
  sm::TransfiniteBoundary b;
  auto add = [&](double x, double y) {
    b.coords.push_back({x, y, 0});
    b.xyz.push_back({x, y, 0});
  };
  for (int i = 0; i < nx; ++i) add(double(i) / nx, 0);
  for (int j = 0; j < ny; ++j) add(1, double(j) / ny);
  for (int i = nx; i > 0; --i) add(double(i) / nx, 1);
  for (int j = ny; j > 0; --j) add(0, double(j) / ny);
  b.corners = {0, static_cast<std::size_t>(nx), static_cast<std::size_t>(nx + ny),
               static_cast<std::size_t>(2 * nx + ny)};
  return b;
}

sm::Vec3 at(const sm::TransfiniteBoundary& b, const sm::TransfiniteResult& r, std::uint32_t k) {
  return k < b.coords.size() ? b.coords[k] : r.interior[k - b.coords.size()];
}

double signed_area(const sm::TransfiniteBoundary& b, const sm::TransfiniteResult& r, std::uint32_t p, std::uint32_t q,
                   std::uint32_t s) {
  const sm::Vec3 a = at(b, r, p), c = at(b, r, q), d = at(b, r, s);
  return 0.5 * ((c.x - a.x) * (d.y - a.y) - (c.y - a.y) * (d.x - a.x));
}

}  // namespace transfinite_surface_testing

TEST_CASE("transfinite surface: a 3 x 2 grid of quadrangles on the unit square") {
  using namespace transfinite_surface_testing;
  const sm::TransfiniteBoundary b = square(3, 2);
  const sm::TransfiniteResult r = sm::fill_transfinite(b, sm::TriangleArrangement::Left, /*quads=*/true);
  REQUIRE(r.ok());
  CHECK(r.L == 3);
  CHECK(r.H == 2);
  CHECK(r.triangles.empty());
  REQUIRE(r.quads.size() == 6);
  // Interior nodes (i, j) for i = 1..2, j = 1: exactly (i/3, 1/2).
  REQUIRE(r.interior.size() == 2);
  CHECK(r.interior[0].x == doctest::Approx(1.0 / 3).epsilon(1e-14));
  CHECK(r.interior[0].y == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(r.interior[1].x == doctest::Approx(2.0 / 3).epsilon(1e-14));
  double area = 0;
  for (const auto& q : r.quads) {
    const double a1 = signed_area(b, r, q[0], q[1], q[2]), a2 = signed_area(b, r, q[0], q[2], q[3]);
    CHECK(a1 > 0);   // counter-clockwise, as the boundary
    CHECK(a2 > 0);
    area += a1 + a2;
  }
  CHECK(area == doctest::Approx(1.0));
}

TEST_CASE("transfinite surface: Left, Right and Alternate diagonals") {
  using namespace transfinite_surface_testing;
  const sm::TransfiniteBoundary b = square(2, 2);
  auto diagonals = [&](sm::TriangleArrangement a) {
    const sm::TransfiniteResult r = sm::fill_transfinite(b, a, false);
    REQUIRE(r.ok());
    CHECK(r.triangles.size() == 8);
    // Per cell, whether its diagonal joins its lower-left and upper-right corners.
    std::set<std::pair<int, int>> rising;
    for (const auto& t : r.triangles) {
      CHECK(signed_area(b, r, t[0], t[1], t[2]) > 0);
      for (int e = 0; e < 3; ++e) {
        const sm::Vec3 p = at(b, r, t[e]), q = at(b, r, t[(e + 1) % 3]);
        if (std::abs(std::abs(p.x - q.x) - 0.5) < 1e-12 && std::abs(std::abs(p.y - q.y) - 0.5) < 1e-12 &&
            (p.x - q.x) * (p.y - q.y) > 0)
          rising.insert(
              {static_cast<int>(std::min(p.x, q.x) * 2 + 0.5), static_cast<int>(std::min(p.y, q.y) * 2 + 0.5)});
      }
    }
    return rising;
  };
  CHECK(diagonals(sm::TriangleArrangement::Left).empty());
  CHECK(diagonals(sm::TriangleArrangement::Right).size() == 4);
  // Alternate(Right): rising where i + j is odd.
  CHECK(diagonals(sm::TriangleArrangement::AlternateRight) == std::set<std::pair<int, int>>{{0, 1}, {1, 0}});
  CHECK(diagonals(sm::TriangleArrangement::AlternateLeft) == std::set<std::pair<int, int>>{{0, 0}, {1, 1}});
}

TEST_CASE("transfinite surface: corners against the chain, a 3-sided face, unequal sides") {
  using namespace transfinite_surface_testing;
  sm::TransfiniteBoundary b = square(3, 2);
  // Corners listed clockwise: still a counter-clockwise mesh (the chain's way).
  b.corners = {0, 8, 5, 3};
  const sm::TransfiniteResult r = sm::fill_transfinite(b, sm::TriangleArrangement::Left, true);
  REQUIRE(r.ok());
  CHECK(r.L == 2);
  CHECK(r.H == 3);
  for (const auto& q : r.quads) CHECK(signed_area(b, r, q[0], q[1], q[2]) > 0);

  // A triangle (0,0) (1,0) (0,1) with 2 edges per side: corner 0 is the apex.
  sm::TransfiniteBoundary t;
  for (sm::Vec3 p : {sm::Vec3{0, 0, 0}, sm::Vec3{0.5, 0, 0}, sm::Vec3{1, 0, 0}, sm::Vec3{0.5, 0.5, 0},
                     sm::Vec3{0, 1, 0}, sm::Vec3{0, 0.5, 0}})
    t.coords.push_back(p), t.xyz.push_back(p);
  t.corners = sm::implicit_transfinite_corners(std::vector<std::size_t>{0, 2, 4}, 6);
  const sm::TransfiniteResult tr = sm::fill_transfinite(t, sm::TriangleArrangement::Left, false);
  REQUIRE(tr.ok());
  CHECK(tr.interior.size() == 1);
  CHECK(tr.triangles.size() == 6);   // H = 2 fan triangles at the apex, 2 per further cell

  sm::TransfiniteBoundary bad = square(3, 2);
  bad.corners = {0, 3, 5, 7};   // sides of 3, 2, 2 and 3 edges
  const sm::TransfiniteResult br = sm::fill_transfinite(bad, sm::TriangleArrangement::Left, false);
  CHECK_FALSE(br.ok());
  CHECK(br.error == "cannot be meshed using the transfinite algo (divisions 2 != 3 or 3 != 2)");
}

TEST_CASE("transfinite surface: the 2D driver on a Plane Surface with transfinite curves") {
  sm::geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {2, 0, 0}).ok());
  REQUIRE(m.add_point(3, {2, 1, 0}).ok());
  REQUIRE(m.add_point(4, {0, 1, 0}).ok());
  for (int c = 1; c <= 4; ++c) REQUIRE(m.add_curve(c, sm::geo::CurveKind::Line, {c, c % 4 + 1}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  sm::MeshConstraints mc;
  sm::TransfiniteCurveSpec five;
  five.nodes = 5;
  sm::TransfiniteCurveSpec three;
  three.nodes = 3;
  mc.curves = {{1, five}, {2, three}, {3, five}, {4, three}};
  mc.surfaces[1] = {};
  sm::Mesh1dOptions o1;
  o1.constraints = &mc;
  sm::Mesh1dResult r1 = sm::mesh_curves(m, o1);
  REQUIRE(r1.ok());
  CHECK(r1.mesh.curves.at(1).nodes.size() == 5);
  sm::Mesh2dOptions o2;
  o2.constraints = &mc;
  SUBCASE("triangles") {
    const sm::Mesh2dResult r2 = sm::mesh_surfaces(m, r1.mesh, o2);
    REQUIRE(r2.ok());
    const sm::SurfaceMesh& s = r1.mesh.surfaces.at(1);
    CHECK(s.triangles.size() == 16);
    CHECK(s.interior_nodes.size() == 3);
    CHECK(r1.mesh.nodes[s.interior_nodes[0]].xyz.x == doctest::Approx(0.5).epsilon(1e-14));
    CHECK(r1.mesh.nodes[s.interior_nodes[0]].xyz.y == doctest::Approx(0.5).epsilon(1e-14));
  }
  SUBCASE("recombined") {
    mc.recombine.insert(1);
    const sm::Mesh2dResult r2 = sm::mesh_surfaces(m, r1.mesh, o2);
    REQUIRE(r2.ok());
    CHECK(r1.mesh.surfaces.at(1).quads.size() == 8);
    CHECK(r1.mesh.surfaces.at(1).triangles.empty());
    CHECK(r2.stats.quads == 8);
  }
  SUBCASE("unequal sides: an error naming the surface") {
    mc.curves[3].nodes = 4;
    sm::Mesh1dResult again = sm::mesh_curves(m, o1);
    const sm::Mesh2dResult r2 = sm::mesh_surfaces(m, again.mesh, o2);
    REQUIRE_FALSE(r2.ok());
    CHECK(r2.error.problem == sm::MeshProblem::TransfiniteSidesUnequal4);
    CHECK(r2.error.surface == 1);
    CHECK(r2.error.numbers == std::array<long long, 5>{3, 4, 2, 2, 0});
  }
}
