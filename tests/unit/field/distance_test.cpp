#include "field/distance.h"

#include <cmath>
#include <random>

#include <doctest/doctest.h>

#include "field/error.h"
#include "field/knn.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

TEST_CASE("distance: points and curve samples from the context, brute-force oracle") {
  std::vector<Vec3> curve;
  BuildContext ctx;
  ctx.point_position = [](int tag) -> std::optional<Vec3> {
    if (tag == 1) return Vec3{0, 0, 1};
    return std::nullopt;
  };
  ctx.curve_samples = [&](int tag, int n) -> std::optional<std::vector<Vec3>> {
    if (tag != 3) return std::nullopt;
    std::vector<Vec3> s;
    for (int i = 1; i <= n - 2; ++i) {
      const double t = static_cast<double>(i) / (n - 1) * 3.14159;
      s.push_back({std::cos(t), std::sin(t), 0});
    }
    curve = s;
    return s;
  };
  FieldSet fs;
  fs.define(1, "Distance");
  fs.set(1, "PointsList", std::vector<double>{1});
  fs.set(1, "CurvesList", std::vector<double>{3});
  fs.set(1, "Sampling", 50.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Vec3> q(200);
  for (Vec3& p : q) p = {u(rng), u(rng), u(rng)};
  const std::vector<double> h = sm::field::testing::eval_field(fs, 1, q, ctx);
  REQUIRE(curve.size() == 48);
  std::vector<Vec3> all = curve;
  all.push_back({0, 0, 1});
  std::vector<double> bf(q.size());
  nearest_brute_force(all, q, bf);
  for (std::size_t i = 0; i < q.size(); ++i) CHECK(h[i] == doctest::Approx(bf[i]).epsilon(1e-12));
  CHECK(eval1(fs, 1, {0, 0, 3}, ctx) == doctest::Approx(2));
}

TEST_CASE("distance: missing entities and non-finite samples are rejected") {
  FieldSet fs;
  fs.define(1, "Distance");
  fs.set(1, "PointsList", std::vector<double>{4});
  try {
    fs.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::BadValue);
    CHECK(e.option == "PointsList");
    CHECK(e.field_id == 1);
  }
  CHECK_THROWS_AS(make_distance_field({{0, 0, 0}, {std::nan(""), 0, 0}}), FieldError);
  // No samples at all: no constraint, as Gmsh.
  FieldSet empty;
  empty.define(1, "Distance");
  CHECK(eval1(empty, 1, {1, 2, 3}) == 1e22);
}

TEST_CASE("distance: with a compat_note callback, missing points and curves are skipped as Gmsh skips them") {
  BuildContext ctx;
  ctx.point_position = [](int tag) -> std::optional<Vec3> {
    if (tag == 1) return Vec3{0, 0, 1};
    return std::nullopt;
  };
  ctx.curve_samples = [](int, int) -> std::optional<std::vector<Vec3>> { return std::nullopt; };
  std::vector<std::string> notes;
  ctx.compat_note = [&](int id, std::string_view option, std::string_view entity, int tag) {
    notes.push_back(std::to_string(id) + " " + std::string(option) + ": " + std::string(entity) + " " +
                    std::to_string(tag));
  };
  FieldSet fs;
  fs.define(1, "Distance");
  fs.set(1, "PointsList", std::vector<double>{4, 1});
  fs.set(1, "CurvesList", std::vector<double>{7});
  CHECK(eval1(fs, 1, {0, 0, 3}, ctx) == doctest::Approx(2));   // the distance to point 1 only
  REQUIRE(notes.size() == 2);
  CHECK(notes[0] == "1 PointsList: Point 4");
  CHECK(notes[1] == "1 CurvesList: Curve 7");
}
