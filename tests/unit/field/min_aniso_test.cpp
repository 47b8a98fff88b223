// MinAniso (field/min_aniso.cpp): the minimum of isotropic inputs, capped at 1e11 as
// Gmsh 4.8.4's scalar evaluation is.
#include <doctest/doctest.h>

#include "field/field_set.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;

TEST_CASE("MinAniso: the minimum of isotropic fields, Gmsh's 1e11 cap, an empty list") {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("x"));
  fs.define(2, "MathEval");
  fs.set(2, "F", std::string("2 - x"));
  fs.define(3, "Constant");
  fs.set(3, "VOut", 1e30);
  fs.define(4, "MinAniso");
  fs.set(4, "FieldsList", std::vector<double>{1, 2});
  fs.define(5, "MinAniso");
  fs.set(5, "FieldsList", std::vector<double>{3});
  fs.define(6, "MinAniso");
  const std::vector<Vec3> pts = {{0.25, 0, 0}, {1, 0, 0}, {1.5, 0, 0}};
  BuiltFields b = fs.build_all({});
  std::vector<double> h(pts.size());
  b.get(4)->eval(pts, h);
  CHECK(h == std::vector<double>{0.25, 1, 0.5});
  b.get(5)->eval(pts, h);
  CHECK(h[0] == 1e11);
  b.get(6)->eval(pts, h);
  CHECK(h[2] == 1e11);
}
