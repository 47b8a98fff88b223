#include "field/math_expr.h"

#include <cmath>
#include <numbers>

#include <doctest/doctest.h>

#include "field/error.h"

using namespace sm;
using namespace sm::field;

namespace {

double ev(const char* text, Vec3 p = {0.5, -0.25, 2}, std::vector<double> f = {}) {
  MathExpr e = MathExpr::compile(text);
  std::vector<std::vector<double>> cols;
  for (double v : f) cols.push_back({v});
  std::vector<std::span<const double>> spans(cols.begin(), cols.end());
  double out = 0;
  std::vector<Vec3> pts = {p};
  e.eval(pts, spans, std::span<double>(&out, 1));
  return out;
}

int error_column(const char* text) {
  try {
    MathExpr::compile(text);
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::ParseError);
    return e.column;
  }
  return 0;
}

}  // namespace

TEST_CASE("math expr: operators, precedence and MathEx's sign rule") {
  CHECK(ev("1 + 2 * 3") == 7);
  CHECK(ev("(1 + 2) * 3") == 9);
  CHECK(ev("7 % 3") == 1);
  CHECK(ev("2^3") == 8);
  CHECK(ev("2 * 3^2") == 18);
  CHECK(ev("-x^2", {3, 0, 0}) == 9);  // the sign binds tighter than '^'
  CHECK(ev("-2^2") == 4);
  CHECK(ev("-x + 1", {3, 0, 0}) == -2);
  CHECK(ev("2*(-x)", {3, 0, 0}) == -6);
  CHECK(ev("1e-3 * 2E2") == doctest::Approx(0.2));
  CHECK(ev(".5 + 1.") == 1.5);
  CHECK(ev("x + y + z") == 2.25);
  CHECK(ev("Pi") == std::numbers::pi);
  CHECK(ev("pi * e") == doctest::Approx(std::numbers::pi * std::numbers::e));
  CHECK(ev("8 / 4 / 2") == 1);
  CHECK(ev("10 - 4 - 3") == 3);
}

TEST_CASE("math expr: functions in lowercase or Capitalised") {
  CHECK(ev("Sin(0.5)") == doctest::Approx(std::sin(0.5)));
  CHECK(ev("sqrt(16) + Sqrt(9)") == 7);
  CHECK(ev("Fabs(-2) + abs(-3)") == 5);
  CHECK(ev("log10(1000)") == doctest::Approx(3));
  CHECK(ev("Exp(Log(3))") == doctest::Approx(3));
  CHECK(ev("atanh(0.5)") == doctest::Approx(std::atanh(0.5)));
  CHECK(ev("floor(-1.5) + ceil(1.2) + trunc(-1.7)") == -2 + 2 - 1);
  CHECK(ev("round(2.5)") == 3);
  CHECK(ev("sign(-3) + sign(0) + sign(4)") == 0);
  CHECK(ev("step(-1) + step(0) + step(2)") == 2);
  CHECK(ev("deg(Pi)") == doctest::Approx(180));
  CHECK(ev("rad(180)") == doctest::Approx(std::numbers::pi));
  CHECK(ev("fac(5)") == doctest::Approx(120));
  CHECK(ev("min(3, x, 7)") == 0.5);
  CHECK(ev("max(3, x, 7)") == 7);
  CHECK(ev("sum(1, 2, 3, 4)") == 10);
  CHECK(ev("med(5, 1, 3)") == 3);
  CHECK(ev("med(4, 1, 3, 2)") == 2.5);
  const double r1 = ev("rand()"), r2 = ev("rand()");
  CHECK(r1 == r2);  // deterministic per point
  CHECK(r1 >= 0);
  CHECK(r1 < 1);
}

TEST_CASE("math expr: F<n> references, 'Fabs' is a function") {
  MathExpr e = MathExpr::compile("F4^3 + F2 * F4 + Fabs(F10)");
  CHECK(e.field_refs() == std::vector<int>{4, 2, 10});
  CHECK(ev("F4^3 + F2 * F4 + Fabs(F10)", {}, {2, 5, -1}) == 8 + 10 + 1);
  CHECK_THROWS_AS(MathExpr::compile("F1 + x", /*allow_fields=*/false), FieldError);
}

TEST_CASE("math expr: constant subtrees are folded") {
  CHECK(MathExpr::compile("2 * Pi * 3 + sqrt(4)").size() == 0);
  CHECK(MathExpr::compile("x * (2 + 3)").size() == 2);  // load x, multiply
  CHECK(ev("x^2 + (x+1)^2", {3, 0, 0}) == 25);
}

TEST_CASE("math expr: errors carry the column") {
  CHECK(error_column("2*-x") == 3);
  CHECK(error_column("2^3^2") == 4);
  CHECK(error_column("x +") == 4);
  CHECK(error_column("atan2(y, x)") == 1);
  CHECK(error_column("x $ 2") == 3);
  CHECK(error_column("sin(x") == 6);
  CHECK(error_column("(x + 1") == 7);
  CHECK(error_column("x)") == 2);
  CHECK(error_column("sin(1, 2)") == 1);
  CHECK(error_column("max()") == 1);
  CHECK(error_column("") == 1);
  CHECK(error_column("foo + 1") == 1);
  CHECK(error_column("2 x") == 3);
  CHECK(error_column("x < 1") == 3);
}

TEST_CASE("math expr: batches longer than one chunk") {
  MathExpr e = MathExpr::compile("x * 2 + sin(y) - F3");
  std::vector<Vec3> pts(1000);
  std::vector<double> f(1000), out(1000);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts[i] = {static_cast<double>(i), 0.001 * static_cast<double>(i), 0};
    f[i] = 0.5 * static_cast<double>(i);
  }
  std::vector<std::span<const double>> cols = {f};
  e.eval(pts, cols, out);
  for (std::size_t i = 0; i < pts.size(); ++i)
    CHECK(out[i] == doctest::Approx(2.0 * i + std::sin(0.001 * i) - 0.5 * i));
}
