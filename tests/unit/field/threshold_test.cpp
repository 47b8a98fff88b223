#include <cmath>
#include <optional>
#include <string>
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

TEST_CASE("threshold: inside a Min, a Distance is searched only where it can lower the size; same sizes") {
  // Min(Threshold(Distance to A), Threshold(Distance to B)) against the same Min over
  // MathEval distances (evaluated everywhere): identical sizes, including where one
  // criterion's size is below the other's SizeMin (B not searched at all) and where
  // both are at SizeMax.
  BuildContext ctx;
  const std::vector<Vec3> where = {{0, 0, 0}, {1, 0, 0}, {4, 1, 0}, {6, -1, 0}};
  ctx.point_position = [&](int tag) -> std::optional<Vec3> {
    if (tag < 1 || tag > 4) return std::nullopt;
    return where[static_cast<std::size_t>(tag - 1)];
  };
  const auto dist_to = [&](int a, int b) {
    std::string f = "Min(";
    for (int t = a; t <= b; ++t) {
      const Vec3& p = where[static_cast<std::size_t>(t - 1)];
      if (t > a) f += t == b ? ", " : ", Min(";
      f += "Sqrt((x-(" + std::to_string(p.x) + "))^2+(y-(" + std::to_string(p.y) + "))^2+z^2)";
    }
    for (int t = a + 2; t <= b; ++t) f += ")";
    return f + ")";
  };
  FieldSet fs;
  fs.define(1, "Distance");
  fs.set(1, "PointsList", std::vector<double>{1, 2});
  fs.define(2, "Distance");
  fs.set(2, "PointsList", std::vector<double>{3, 4});
  fs.define(3, "MathEval");
  fs.set(3, "F", dist_to(1, 2));
  fs.define(4, "MathEval");
  fs.set(4, "F", dist_to(3, 4));
  // Fields 11, 12: Thresholds of the Distances; 13, 14: of the MathEvals.
  for (int id : {11, 12, 13, 14}) {
    const bool first = id % 2 == 1;
    fs.define(id, "Threshold");
    fs.set(id, "InField", static_cast<double>(id <= 12 ? (first ? 1 : 2) : (first ? 3 : 4)));
    fs.set(id, "SizeMin", first ? 0.1 : 0.3);
    fs.set(id, "SizeMax", 1.0);
    fs.set(id, "DistMin", 0.2);
    fs.set(id, "DistMax", 3.0);
  }
  fs.define(20, "Min");
  fs.set(20, "FieldsList", std::vector<double>{11, 12});
  fs.define(21, "Min");
  fs.set(21, "FieldsList", std::vector<double>{13, 14});
  std::vector<Vec3> q;
  for (int i = -30; i <= 110; ++i)
    for (int j = -20; j <= 20; j += 5) q.push_back({0.1 * i, 0.1 * j, 0.05 * (j % 3)});
  q.push_back({4, 4, 0});   // 3 from point 3: at DistMax
  const std::vector<double> fast = sm::field::testing::eval_field(fs, 20, q, ctx);
  const std::vector<double> slow = sm::field::testing::eval_field(fs, 21, q, ctx);
  const std::vector<double> first = sm::field::testing::eval_field(fs, 11, q, ctx);
  int below_other_min = 0, both_max = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    CHECK(fast[i] == doctest::Approx(slow[i]).epsilon(1e-12));
    below_other_min += first[i] < 0.3 ? 1 : 0;
    both_max += fast[i] == 1.0 ? 1 : 0;
  }
  CHECK(below_other_min > 20);
  CHECK(both_max > 20);
}

// A Min lowers h through its Threshold of a Distance in pieces of at most 256 points, each
// with its scratch on the stack (src/field/threshold.cpp): the sizes of a large batch, of
// the refiners' small ones and of single points are the same numbers.
TEST_CASE("threshold: inside a Min, the sizes do not depend on how the points are batched") {
  BuildContext ctx;
  std::vector<Vec3> where;
  for (int i = 0; i < 40; ++i) where.push_back({std::cos(0.3 * i) * (1 + 0.02 * i), std::sin(0.3 * i), 0});
  ctx.point_position = [&](int tag) -> std::optional<Vec3> {
    if (tag < 1 || tag > static_cast<int>(where.size())) return std::nullopt;
    return where[static_cast<std::size_t>(tag - 1)];
  };
  FieldSet fs;
  fs.define(1, "Distance");
  std::vector<double> tags;
  for (std::size_t t = 1; t <= where.size(); ++t) tags.push_back(static_cast<double>(t));
  fs.set(1, "PointsList", tags);
  fs.define(2, "Threshold");
  fs.set(2, "InField", 1.0);
  fs.set(2, "SizeMin", 0.05);
  fs.set(2, "SizeMax", 0.5);
  fs.set(2, "DistMin", 0.1);
  fs.set(2, "DistMax", 1.5);
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("0.2 + 0.1 * x"));
  fs.define(4, "Min");
  fs.set(4, "FieldsList", std::vector<double>{3, 2});
  std::vector<Vec3> q;
  for (int i = -40; i <= 40; ++i)
    for (int j = -10; j <= 10; ++j) q.push_back({0.05 * i, 0.2 * j, 0.01 * (i % 5)});
  REQUIRE(q.size() > 1000);
  const std::vector<double> whole = sm::field::testing::eval_field(fs, 4, q, ctx);
  const std::vector<double> alone = sm::field::testing::eval_field(fs, 2, q, ctx);
  int by_shore = 0;
  for (std::size_t i = 0; i < q.size(); ++i) by_shore += alone[i] < 0.2 + 0.1 * q[i].x ? 1 : 0;
  CHECK(by_shore > 300);
  CHECK(by_shore < static_cast<int>(q.size()) - 300);
  BuiltFields built = fs.build(4, ctx);
  for (const std::size_t batch : {std::size_t{1}, std::size_t{15}, std::size_t{256}, std::size_t{300}}) {
    std::vector<double> h(q.size());
    for (std::size_t first = 0; first < q.size(); first += batch) {
      const std::size_t n = std::min(batch, q.size() - first);
      built.get(4)->eval(std::span<const Vec3>(q.data() + first, n), std::span<double>(h.data() + first, n));
    }
    for (std::size_t i = 0; i < q.size(); ++i) CHECK(h[i] == whole[i]);
  }
}
