#include <cmath>

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
