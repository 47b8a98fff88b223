// mesh/periodic_curve: the Translate and Rotate maps, the end-point check that gives the
// direction, and a periodic curve's mesh as a copy of its source's (by the map onto an
// arc, by the parameters without one).
#include "mesh/periodic_curve.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "mesh/mesh1d.h"

namespace periodic_curve_testing {

// A square of side 1 whose bottom (curve 1) is graded: 0.02 at point 1, 0.2 at point 2.
sm::geo::Model square() {
  sm::geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.02).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.2).ok());
  REQUIRE(m.add_point(3, {1, 1, 0}, 0.1).ok());
  REQUIRE(m.add_point(4, {0, 1, 0}, 0.1).ok());
  REQUIRE(m.add_curve(1, sm::geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, sm::geo::CurveKind::Line, {2, 3}).ok());
  REQUIRE(m.add_curve(3, sm::geo::CurveKind::Line, {3, 4}).ok());
  REQUIRE(m.add_curve(4, sm::geo::CurveKind::Line, {4, 1}).ok());
  return m;
}

}  // namespace periodic_curve_testing

TEST_CASE("periodic curve: a quarter turn about z through (0.5, 0.5) as Gmsh's matrix") {
  const std::vector<double> a = sm::periodic_rotation({0, 0, 2}, {0.5, 0.5, 0}, std::numbers::pi / 2);
  REQUIRE(a.size() == 16);
  const sm::Vec3 p = sm::apply_affine(a, {1, 0, 0});   // (0.5, -0.5) from the centre -> (0.5, 0.5)
  CHECK(p.x == doctest::Approx(1.0));
  CHECK(p.y == doctest::Approx(1.0));
  CHECK(a[15] == 1.0);
  CHECK(sm::periodic_rotation({0, 0, 0}, {0, 0, 0}, 1.0).empty());
  const sm::Vec3 q = sm::apply_affine(sm::periodic_translation({0, 1, 0}), {0.25, 0, 3});
  CHECK(q == sm::Vec3{0.25, 1, 3});
}

TEST_CASE("periodic curve: the map's direction from the end points, or none") {
  const sm::geo::Model m = periodic_curve_testing::square();
  const double tol = 1e-8;
  CHECK(sm::periodic_orientation(m, 3, 1, sm::periodic_translation({0, 1, 0}), tol) == -1);
  CHECK(sm::periodic_orientation(m, 4, 1, sm::periodic_rotation({0, 0, 1}, {0.5, 0.5, 0}, -std::numbers::pi / 2),
                                 tol) == 1);
  std::pair<double, double> d;
  CHECK_FALSE(sm::periodic_orientation(m, 3, 1, sm::periodic_translation({0, 2, 0}), tol, &d));
  CHECK(d.first == doctest::Approx(1.0));
}

TEST_CASE("periodic curve: the copy has the source's nodes, moved by the map") {
  sm::geo::Model m = periodic_curve_testing::square();
  sm::MeshConstraints c;
  c.periodic_curves[3] = {1, -1, sm::periodic_translation({0, 1, 0})};
  c.periodic_curves[2] = {4, -1, {}};   // no map: the parameters of curve -4
  c.periodic_points[3] = {1, {}};
  sm::Mesh1dOptions opt;
  opt.constraints = &c;
  const sm::Mesh1dResult r = sm::mesh_curves(m, opt);
  REQUIRE(r.ok());
  const std::vector<std::uint32_t> top = r.mesh.curve_nodes(3), bottom = r.mesh.curve_nodes(-1);
  REQUIRE(top.size() == bottom.size());
  CHECK(top.size() > 12);   // graded: more than the 11 nodes of size 0.1
  for (std::size_t i = 0; i < top.size(); ++i) {
    const sm::Vec3 a = r.mesh.nodes[top[i]].xyz, b = r.mesh.nodes[bottom[i]].xyz;
    CHECK(a.x == doctest::Approx(b.x).epsilon(1e-12));
    CHECK(a.y == doctest::Approx(1.0));
  }
  const std::vector<std::uint32_t> right = r.mesh.curve_nodes(2), left = r.mesh.curve_nodes(-4);
  REQUIRE(right.size() == left.size());
  for (std::size_t i = 0; i < right.size(); ++i)
    CHECK(r.mesh.nodes[right[i]].xyz.y == doctest::Approx(r.mesh.nodes[left[i]].xyz.y).epsilon(1e-12));
  // The correspondences: point 3 with point 1, then the curves' node pairs, ends included.
  REQUIRE(r.mesh.periodic.size() == 3);
  CHECK(r.mesh.periodic[0].dim == 0);
  CHECK(r.mesh.periodic[1].tag == 2);
  CHECK(r.mesh.periodic[2].nodes.size() == top.size());
  CHECK(r.mesh.periodic[2].affine.size() == 16);
}

TEST_CASE("periodic curve: curves copying one another in a cycle are refused") {
  const sm::geo::Model m = periodic_curve_testing::square();
  sm::MeshConstraints c;
  c.periodic_curves[3] = {1, -1, {}};
  c.periodic_curves[1] = {3, -1, {}};
  sm::Mesh1dOptions opt;
  opt.constraints = &c;
  const sm::Mesh1dResult r = sm::mesh_curves(m, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.problem == sm::MeshProblem::PeriodicCycle);
  CHECK(((r.error.numbers[0] == 1 && r.error.numbers[1] == 3) || (r.error.numbers[0] == 3 && r.error.numbers[1] == 1)));
}
