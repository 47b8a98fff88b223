#include "field/min_max.h"

#include <doctest/doctest.h>

#include "test_util.h"

using namespace sm;
using namespace sm::field;

TEST_CASE("min/max: values, empty lists and the argmin report") {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("x"));
  fs.define(2, "MathEval");
  fs.set(2, "F", std::string("2 - x"));
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("0.75"));
  fs.define(4, "Min");
  fs.set(4, "FieldsList", std::vector<double>{1, 2, 3});
  fs.define(5, "Max");
  fs.set(5, "FieldsList", std::vector<double>{1, 2, 3});
  fs.define(6, "Min");
  fs.define(7, "Max");
  const std::vector<Vec3> pts = {{0.25, 0, 0}, {1, 0, 0}, {1.5, 0, 0}, {0.75, 0, 0}};
  BuiltFields b = fs.build_all({});
  std::vector<double> h(pts.size());
  std::vector<int> which(pts.size());
  REQUIRE(eval_argmin(*b.get(4), nullptr, pts, h, which));
  CHECK(h == std::vector<double>{0.25, 0.75, 0.5, 0.75});
  CHECK(which == std::vector<int>{1, 3, 2, 1});  // ties go to the first listed
  b.get(5)->eval(pts, h);
  CHECK(h == std::vector<double>{1.75, 1, 1.5, 1.25});
  CHECK(!eval_argmin(*b.get(5), nullptr, pts, h, which));
  b.get(6)->eval(pts, h);
  CHECK(h[0] == 1e22);
  b.get(7)->eval(pts, h);
  CHECK(h[0] == -1e22);
  REQUIRE(eval_argmin(*b.get(6), nullptr, pts, h, which));
  CHECK(which[0] == -1);
}
