// exact/quality.h: rho = 2 r_in / r_circ in the plane and in space, one formula for
// the refiners, the optimiser, the statistics and the writers; beside it eta, gamma and
// the quadrangle corner quality, reached here from sm_exact alone.
#include "exact/quality.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace sm;

namespace {
// Right isosceles triangle: r_in = (2 - sqrt2) / 2, r_circ = sqrt2 / 2.
const double kRightIsosceles = 2 * (2 - std::sqrt(2.0)) / std::sqrt(2.0);
}  // namespace

TEST_CASE("rho in the plane: equilateral, right isosceles, flat, coincident") {
  CHECK(rho(Vec2{0, 0}, Vec2{1, 0}, Vec2{0.5, std::sqrt(0.75)}) == doctest::Approx(1));
  CHECK(rho(Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}) == doctest::Approx(kRightIsosceles));
  CHECK(rho(Vec2{0, 0}, Vec2{1, 0}, Vec2{2, 0}) == 0);
  CHECK(rho(Vec2{0, 0}, Vec2{0, 0}, Vec2{2, 0}) == 0);
  CHECK(rho(Vec2{3, 3}, Vec2{3, 3}, Vec2{3, 3}) == 0);
}

TEST_CASE("rho in space: equilateral, right isosceles, flat, coincident") {
  CHECK(rho(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0.5, std::sqrt(0.75), 0}) == doctest::Approx(1));
  CHECK(rho(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 5e-17}) == doctest::Approx(kRightIsosceles));
  CHECK(rho(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}) == 0);
  CHECK(rho(Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{2, 0, 0}) == 0);
  // Tilted out of every coordinate plane: still equilateral.
  CHECK(rho(Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}) == doctest::Approx(1));
}

TEST_CASE("rho: orientation and vertex order do not matter; rho_ccw filters clockwise") {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    const Vec2 a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)};
    const double q = rho(a, b, c);
    CHECK(q >= 0);
    CHECK(q <= 1 + 1e-12);
    CHECK(rho(b, c, a) == doctest::Approx(q));
    CHECK(rho(a, c, b) == doctest::Approx(q));
    // The plane and the space formulas agree on a triangle in z = 0.
    CHECK(rho(Vec3{a.x, a.y, 0}, Vec3{b.x, b.y, 0}, Vec3{c.x, c.y, 0}) == doctest::Approx(q));
    const RhoTerms t = rho_terms(a, b, c);
    CHECK(t.area2 == cross(b - a, c - a));
    if (t.area2 > 0) {
      CHECK(rho_ccw(a, b, c) == q);
      CHECK(rho_ccw(a, c, b) == -1);
      CHECK(t.num / t.den == q);
    } else if (t.area2 < 0) {
      CHECK(rho_ccw(a, b, c) == -1);
      CHECK(rho_ccw(a, c, b) == doctest::Approx(q));
    }
  }
  CHECK(rho_ccw(Vec2{0, 0}, Vec2{1, 0}, Vec2{2, 0}) == -1);
}

TEST_CASE("quality: eta, gamma and the quadrangle corner quality beside rho") {
  const Vec2 a{0, 0}, b{1, 0}, c{0.5, std::sqrt(0.75)};
  CHECK(eta(a, b, c) == doctest::Approx(1));
  CHECK(gamma(a, b, c) == doctest::Approx(1));
  CHECK(eta(a, b, {2, 0}) == 0);
  CHECK(gamma(a, a, a) == 0);
  // Orientation does not matter to either (rho_ccw is the measure that cares).
  CHECK(eta(a, c, b) == eta(a, b, c));
  CHECK(quad_quality({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}) == doctest::Approx(1));
  CHECK(quad_quality({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}) == doctest::Approx(0));   // a flat corner
  CHECK(quad_quality({0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}) == doctest::Approx(0));   // a null edge
}
