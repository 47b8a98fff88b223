// Gradient, Laplacian, Mean, Curvature, MaxEigenHessian on polynomials whose
// finite differences are exact (or known).
#include <cmath>

#include <doctest/doctest.h>

#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

namespace {

FieldSet on(const char* kind, const char* f, double delta) {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string(f));
  fs.define(2, kind);
  fs.set(2, "InField", 1.0);
  fs.set(2, "Delta", delta);
  return fs;
}

}  // namespace

TEST_CASE("gradient: components and norm") {
  FieldSet fs = on("Gradient", "x^2 + 3*y - 2*z", 0.01);
  fs.set(2, "Kind", 0.0);
  CHECK(eval1(fs, 2, {1.5, 0, 0}) == doctest::Approx(3.0));
  fs.set(2, "Kind", 1.0);
  CHECK(eval1(fs, 2, {1.5, 0, 0}) == doctest::Approx(3.0));
  fs.set(2, "Kind", 2.0);
  CHECK(eval1(fs, 2, {1.5, 0, 0}) == doctest::Approx(-2.0));
  fs.set(2, "Kind", 3.0);
  CHECK(eval1(fs, 2, {1.5, 0, 0}) == doctest::Approx(std::sqrt(9.0 + 9 + 4)));
  fs.set(2, "Kind", 4.0);
  CHECK_THROWS(fs.build(2, {}));
}

TEST_CASE("laplacian and mean") {
  FieldSet fs = on("Laplacian", "x^2 + 2*y^2 - z^2 + x*y", 0.1);
  CHECK(eval1(fs, 2, {0.3, -0.7, 2}) == doctest::Approx(2 + 4 - 2));
  FieldSet m = on("Mean", "x^2 + y", 0.5);
  // (6 neighbours + centre)/7 of x^2 + y at (1, 2, 0): x^2 gains 2*delta^2/7.
  CHECK(eval1(m, 2, {1, 2, 0}) == doctest::Approx(3 + 2 * 0.25 / 7));
}

TEST_CASE("curvature: level sets of |X| are spheres, div(n) = 2/r") {
  FieldSet fs = on("Curvature", "sqrt(x^2 + y^2 + z^2)", 1e-3);
  CHECK(eval1(fs, 2, {2, 0, 0}) == doctest::Approx(1.0).epsilon(1e-4));
  CHECK(eval1(fs, 2, {0.3, 0.4, 0}) == doctest::Approx(4.0).epsilon(1e-4));
}

TEST_CASE("max eigen hessian") {
  FieldSet fs = on("MaxEigenHessian", "x^2 + 3*y^2 - 5*z^2 + 2*x*y", 0.1);
  // Hessian [[2,2,0],[2,6,0],[0,0,-10]]: eigenvalues 4 +- sqrt(8), -10.
  CHECK(eval1(fs, 2, {0.2, 0.1, -0.3}) == doctest::Approx(4 + std::sqrt(8.0)));
  FieldSet d = on("MaxEigenHessian", "0 - x^2 - y^2 - z^2", 0.1);
  CHECK(eval1(d, 2, {1, 1, 1}) == doctest::Approx(-2));
  // MathEx's sign binds tighter than '^': -x^2 - y^2 is x^2 - y^2.
  FieldSet q = on("MaxEigenHessian", "-x^2 - y^2 - z^2", 0.1);
  CHECK(eval1(q, 2, {1, 1, 1}) == doctest::Approx(2));
}

TEST_CASE("Delta 0 means bbox diagonal / 1e4") {
  FieldSet fs = on("Gradient", "x^3", 0);
  fs.set(2, "Kind", 0.0);
  BuildContext ctx;
  ctx.bbox_diag = 1e3;  // delta = 0.1
  CHECK(eval1(fs, 2, {1, 0, 0}, ctx) == doctest::Approx(3 + 0.01 / 4));
}
