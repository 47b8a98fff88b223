#include <cmath>
#include <optional>
#include <vector>

#include <doctest/doctest.h>

#include "field/error.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

namespace {

// Field 1 = x (distance stand-in), field 2 = Threshold on it.
FieldSet threshold_on_x() {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("x"));
  fs.define(2, "Threshold");
  fs.set(2, "IField", 1.0);
  fs.set(2, "LcMin", 0.1);
  fs.set(2, "LcMax", 1.0);
  fs.set(2, "DistMin", 2.0);
  fs.set(2, "DistMax", 6.0);
  return fs;
}

}  // namespace

TEST_CASE("threshold: linear ramp, clamps and the paper's alpha") {
  FieldSet fs = threshold_on_x();
  CHECK(eval1(fs, 2, {0, 0, 0}) == doctest::Approx(0.1));
  CHECK(eval1(fs, 2, {2, 0, 0}) == doctest::Approx(0.1));
  CHECK(eval1(fs, 2, {3, 0, 0}) == doctest::Approx(0.1 + 0.25 * 0.9));
  CHECK(eval1(fs, 2, {5, 0, 0}) == doctest::Approx(0.1 + 0.75 * 0.9));
  CHECK(eval1(fs, 2, {6, 0, 0}) == doctest::Approx(1.0));
  CHECK(eval1(fs, 2, {60, 0, 0}) == doctest::Approx(1.0));
}

TEST_CASE("threshold: sigmoid and StopAtDistMax") {
  FieldSet fs = threshold_on_x();
  fs.set(2, "Sigmoid", 1.0);
  const double r = 0.25, s = std::exp(12 * r - 6) / (1 + std::exp(12 * r - 6));
  CHECK(eval1(fs, 2, {3, 0, 0}) == doctest::Approx(0.1 * (1 - s) + s));
  CHECK(eval1(fs, 2, {4, 0, 0}) == doctest::Approx(0.55));
  fs.set(2, "Sigmoid", 0.0);
  fs.set(2, "StopAtDistMax", 1.0);
  CHECK(eval1(fs, 2, {5.99, 0, 0}) < 1);
  CHECK(eval1(fs, 2, {6, 0, 0}) == 1e22);
  CHECK(eval1(fs, 2, {7, 0, 0}) == 1e22);
}

TEST_CASE("threshold: negative or NaN sizes and reversed distances are rejected") {
  FieldSet fs = threshold_on_x();
  fs.set(2, "SizeMin", -0.1);
  try {
    fs.build(2, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::BadValue);
    CHECK(e.field_id == 2);
    CHECK(e.option == "SizeMin");
  }
  fs.set(2, "SizeMin", std::nan(""));
  CHECK_THROWS_AS(fs.build(2, {}), FieldError);
  fs.set(2, "SizeMin", 0.1);
  fs.set(2, "DistMax", 1.0);
  CHECK_THROWS_AS(fs.build(2, {}), FieldError);
}

TEST_CASE("threshold: over a Distance, the search stops at DistMax and the sizes stay the same") {
  // The same Threshold over a Distance field (which stops its search at DistMax) and over
  // a MathEval of that distance (which cannot): identical sizes, linear, sigmoid, a step
  // (DistMin = DistMax) and StopAtDistMax, including points exactly at DistMax.
  BuildContext ctx;
  ctx.point_position = [](int tag) -> std::optional<Vec3> {
    if (tag < 1 || tag > 3) return std::nullopt;
    return Vec3{static_cast<double>(tag), 0, 0};
  };
  std::vector<Vec3> q;
  for (int i = -40; i <= 80; ++i) q.push_back({0.1 * i, 0.5, 0});
  q.push_back({3, 2, 0});   // 2 from point 3: at DistMax below
  struct Case {
    double dmin, dmax, sigmoid, stop;
  };
  for (const Case c : {Case{0.5, 2, 0, 0}, Case{0.5, 2, 1, 0}, Case{2, 2, 0, 0}, Case{0.5, 2, 0, 1}}) {
    CAPTURE(c.dmin);
    CAPTURE(c.sigmoid);
    CAPTURE(c.stop);
    FieldSet fs;
    fs.define(1, "Distance");
    fs.set(1, "PointsList", std::vector<double>{1, 2, 3});
    fs.define(2, "MathEval");
    fs.set(2, "F", std::string("Min(Min(Sqrt((x-1)^2+y^2+z^2), Sqrt((x-2)^2+y^2+z^2)), Sqrt((x-3)^2+y^2+z^2))"));
    for (int id : {3, 4}) {
      fs.define(id, "Threshold");
      fs.set(id, "InField", id == 3 ? 1.0 : 2.0);
      fs.set(id, "SizeMin", 0.1);
      fs.set(id, "SizeMax", 1.0);
      fs.set(id, "DistMin", c.dmin);
      fs.set(id, "DistMax", c.dmax);
      fs.set(id, "Sigmoid", c.sigmoid);
      fs.set(id, "StopAtDistMax", c.stop);
    }
    const std::vector<double> d = sm::field::testing::eval_field(fs, 1, q, ctx);
    const std::vector<double> bounded = sm::field::testing::eval_field(fs, 3, q, ctx);
    const std::vector<double> plain = sm::field::testing::eval_field(fs, 4, q, ctx);
    int far = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      CHECK(bounded[i] == doctest::Approx(plain[i]).epsilon(1e-12));
      far += d[i] > c.dmax ? 1 : 0;
    }
    CHECK(far > 10);
    CHECK(d.back() == doctest::Approx(2).epsilon(1e-15));
  }
}
