// Box, Ball, Cylinder, Constant and Restrict against their formulas.
#include <cmath>

#include <doctest/doctest.h>

#include "field/error.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

TEST_CASE("box: inside (bounds included), ramp over Thickness, outside") {
  FieldSet fs;
  fs.define(1, "Box");
  for (auto [k, v] : {std::pair{"VIn", 0.1}, {"VOut", 1.0}, {"XMin", 0.0}, {"XMax", 1.0},
                      {"YMin", 0.0}, {"YMax", 2.0}, {"ZMin", -1.0}, {"ZMax", 1.0},
                      {"Thickness", 0.5}})
    fs.set(1, k, v);
  CHECK(eval1(fs, 1, {0.5, 1, 0}) == 0.1);
  CHECK(eval1(fs, 1, {1, 2, 1}) == 0.1);
  CHECK(eval1(fs, 1, {1.25, 1, 0}) == doctest::Approx(0.1 + 0.5 * 0.9));
  CHECK(eval1(fs, 1, {1.3, 2.4, 0}) == doctest::Approx(0.1 + 1.0 * 0.9));
  CHECK(eval1(fs, 1, {1.24, 2.32, 0}) == doctest::Approx(0.1 + 0.4 / 0.5 * 0.9));
  CHECK(eval1(fs, 1, {2, 1, 0}) == 1.0);
  fs.set(1, "Thickness", 0.0);
  CHECK(eval1(fs, 1, {1.01, 1, 0}) == 1.0);
}

TEST_CASE("ball and cylinder") {
  FieldSet fs;
  fs.define(1, "Ball");
  for (auto [k, v] : {std::pair{"XCenter", 1.0}, {"YCenter", 0.0}, {"ZCenter", 0.0},
                      {"Radius", 2.0}, {"VIn", 0.2}, {"VOut", 3.0}, {"Thickness", 1.0}})
    fs.set(1, k, v);
  CHECK(eval1(fs, 1, {1, 1.9, 0}) == 0.2);
  CHECK(eval1(fs, 1, {1, 2.5, 0}) == doctest::Approx(0.2 + 0.5 * 2.8));
  CHECK(eval1(fs, 1, {1, 0, 3.5}) == 3.0);
  fs.define(2, "Cylinder");
  for (auto [k, v] : {std::pair{"XAxis", 0.0}, {"YAxis", 0.0}, {"ZAxis", 2.0},
                      {"Radius", 1.0}, {"VIn", 0.5}, {"VOut", 4.0}})
    fs.set(2, k, v);
  CHECK(eval1(fs, 2, {0.5, 0.5, 1.9}) == 0.5);
  CHECK(eval1(fs, 2, {0.5, 0.5, 2.1}) == 4.0);  // beyond the half-height |axis| = 2
  CHECK(eval1(fs, 2, {0.8, 0.7, 0}) == 4.0);    // outside the radius
  fs.set(2, "ZAxis", 0.0);
  CHECK_THROWS_AS(fs.build(2, {}), FieldError);
}

TEST_CASE("constant and restrict use the entity being meshed") {
  FieldSet fs;
  fs.define(1, "Constant");
  fs.set(1, "VIn", 0.3);
  fs.set(1, "VOut", 2.0);
  fs.set(1, "CurvesList", std::vector<double>{4, 7});
  fs.define(2, "Restrict");
  fs.set(2, "InField", 1.0);
  fs.set(2, "FacesList", std::vector<double>{9});
  fs.set(2, "EdgesList", std::vector<double>{7});
  BuiltFields b = fs.build_all({});
  std::vector<Vec3> p = {{0, 0, 0}};
  std::vector<double> h(1);
  b.get(1)->eval_on({1, 7}, p, h);
  CHECK(h[0] == 0.3);
  b.get(1)->eval_on({1, 5}, p, h);
  CHECK(h[0] == 2.0);
  b.get(1)->eval_on({2, 7}, p, h);  // same tag, other dimension
  CHECK(h[0] == 2.0);
  b.get(1)->eval(p, h);
  CHECK(h[0] == 2.0);
  b.get(2)->eval_on({2, 9}, p, h);  // restricted to surface 9: Constant sees surface 9
  CHECK(h[0] == 2.0);
  b.get(2)->eval_on({1, 7}, p, h);
  CHECK(h[0] == 0.3);
  b.get(2)->eval_on({2, 8}, p, h);
  CHECK(h[0] == 1e22);
  b.get(2)->eval(p, h);  // no entity: InField
  CHECK(h[0] == 2.0);
}
