// mesh/periodic_surface: the map a `Periodic Surface` infers from its paired end points
// (a translation, a rotation found from two independent differences, or none).
#include "mesh/periodic_surface.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "mesh/periodic_curve.h"

namespace periodic_surface_testing {

using sm::Vec3;

double miss(const std::vector<double>& affine, Vec3 p, Vec3 q) { return sm::norm(sm::apply_affine(affine, p) - q); }

}  // namespace periodic_surface_testing

using namespace periodic_surface_testing;

TEST_CASE("periodic surface: equal displacements give the translation") {
  std::string why;
  const auto a = sm::infer_periodic_transform({{{0, 0, 0}, {3, 1, 0}}, {{1, 0, 0}, {4, 1, 0}}, {{1, 1, 0}, {4, 2, 0}}},
                                              1e-9, &why);
  REQUIRE(a.size() == 16);
  CHECK(a == sm::periodic_translation({3, 1, 0}));
  CHECK(why.empty());
}

TEST_CASE("periodic surface: a third of a turn about the z axis, two points on it") {
  const double turn = 2 * std::numbers::pi / 3, r = 0.0005, h = 0.0008;
  const Vec3 p1{r, 0, 0}, p2{r, 0, h}, q1{r * std::cos(turn), r * std::sin(turn), 0}, q2{q1.x, q1.y, h};
  std::string why;
  const auto a = sm::infer_periodic_transform({{{0, 0, 0}, {0, 0, 0}}, {p1, q1}, {{0, 0, h}, {0, 0, h}}, {p2, q2}},
                                              1e-14, &why);
  REQUIRE(a.size() == 16);
  CHECK(miss(a, p1, q1) < 1e-17);
  CHECK(miss(a, {0, 0, 5}, {0, 0, 5}) < 1e-14);   // the axis stays
  CHECK(miss(a, {0, r, 0}, {-r * std::sin(turn), r * std::cos(turn), 0}) < 1e-17);
}

TEST_CASE("periodic surface: no rigid map, points in place, points on a line") {
  std::string why;
  CHECK(sm::infer_periodic_transform({{{0, 0, 0}, {3, 0, 0}}, {{1, 0, 0}, {5, 0, 0}}, {{1, 1, 0}, {5, 2, 0}}}, 1e-9,
                                     &why)
            .empty());
  CHECK(why.find("neither a translation nor a rotation") != std::string::npos);
  CHECK(sm::infer_periodic_transform({{{0, 0, 0}, {0, 0, 0}}, {{1, 0, 0}, {1, 0, 0}}}, 1e-9, &why).empty());
  CHECK(why.find("same points") != std::string::npos);
  CHECK(sm::infer_periodic_transform({{{0, 0, 0}, {0, 0, 0}}, {{1, 0, 0}, {-1, 0, 0}}}, 1e-9, &why).empty());
  CHECK(why.find("one line") != std::string::npos);
}
