#include "field/gradation.h"

#include <cmath>

#include <doctest/doctest.h>

#include "field/error.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

namespace {

/// max over 8-neighbour pairs of |h(u) - h(v)| / |X(u) - X(v)| (wrapping).
double max_slope(const LonLatGrid& g, double radius) {
  double worst = 0;
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int jv = j + dj;
          int iv = i + di;
          if ((!di && !dj) || jv < 0 || jv >= g.nlat) continue;
          if (g.period) iv = g.wrap(iv);
          else if (iv < 0 || iv >= g.nlon) continue;
          const double d = norm(point_of(g.lon(i), g.lat(j), radius) - point_of(g.lon(iv), g.lat(jv), radius));
          if (d < 1e-12) {
            CHECK(std::fabs(g.at(i, j) - g.at(iv, jv)) < 1e-9);  // pole rows collapse to a point
            continue;
          }
          worst = std::max(worst, std::fabs(g.at(i, j) - g.at(iv, jv)) / d);
        }
  return worst;
}

}  // namespace

TEST_CASE("gradation: limited grid satisfies |grad h| <= rate, stays below the input, keeps minima") {
  LonLatGrid g;
  g.nlon = 73;  // 5 degrees, -180..180 with the duplicate column
  g.nlat = 37;
  g.lon0 = -180;
  g.lat0 = -90;
  g.dlon = g.dlat = 5;
  g.detect_wrap();
  REQUIRE(g.period == 72);
  g.v.assign(static_cast<std::size_t>(g.nlon) * g.nlat, 1.0);
  // Two small-size spots and a jagged band.
  g.at(10, 18) = 0.01;
  g.at(40, 30) = 0.05;
  for (int i = 0; i < g.nlon; ++i) g.at(i, 5) = 0.2 + 0.1 * (i % 3);
  for (int j = 0; j < g.nlat; ++j) g.at(72, j) = g.at(0, j);
  const LonLatGrid in = g;
  const double rate = 0.3;
  limit_gradation(g, rate, 1);
  CHECK(max_slope(in, 1) > rate);
  CHECK(max_slope(g, 1) <= rate * (1 + 1e-9));
  for (std::size_t k = 0; k < g.v.size(); ++k) CHECK(g.v[k] <= in.v[k]);
  CHECK(g.at(10, 18) == 0.01);
  CHECK(g.at(40, 30) == 0.05);
  // Next to the 0.01 spot the size is 0.01 + rate * chord (one step east).
  const double chord = norm(point_of(g.lon(10), 0, 1) - point_of(g.lon(11), 0, 1));
  CHECK(g.at(11, 18) == doctest::Approx(0.01 + rate * chord));
  // Duplicate column stays equal to column 0.
  for (int j = 0; j < g.nlat; ++j) CHECK(g.at(72, j) == g.at(0, j));
}

TEST_CASE("gradation field: a point source graded on the sphere through the field set") {
  // Input: 0.01 at the grid node (lon 0, lat 0) only (the ball is smaller
  // than the 1-degree spacing), 1 elsewhere.
  FieldSet fs;
  fs.define(1, "Ball");
  fs.set(1, "XCenter", 1.0);
  fs.set(1, "Radius", 0.005);
  fs.set(1, "VIn", 0.01);
  fs.set(1, "VOut", 1.0);
  fs.define(2, "Gradation");
  fs.set(2, "InField", 1.0);
  fs.set(2, "Rate", 0.2);
  fs.set(2, "Resolution", 1.0);
  const Vec3 src = point_of(0, 0, 1);
  // The size grows like 0.01 + 0.2 d with d the distance along the sphere
  // (a path of short chords), capped by the input; the 8-neighbour graph
  // distance overestimates d by at most ~8%.
  for (double lon : {5.0, 12.0, 30.0, -45.0, 180.0}) {
    const Vec3 p = point_of(lon, lon == 180 ? 0 : 7, 1);
    const double arc = 2 * std::asin(norm(p - src) / 2);
    const double ideal = std::min(1.0, 0.01 + 0.2 * arc);
    const double h = eval1(fs, 2, p);
    CHECK(h >= ideal * 0.97);
    CHECK(h <= ideal * 1.09);
  }
  fs.set(2, "Rate", 0.5);  // 0.01 + 0.5 * 2.6 > 1: the input caps the cone
  CHECK(eval1(fs, 2, point_of(150, 0, 1)) == doctest::Approx(1.0));
  fs.set(2, "Rate", -1.0);
  CHECK_THROWS_AS(fs.build(2, {}), FieldError);
  fs.set(2, "Rate", 0.2);
  fs.set(1, "VIn", -0.5);  // a negative input size is reported with its lon/lat
  try {
    fs.build(2, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::BadValue);
    CHECK(e.field_id == 2);
    CHECK(std::string(e.what()).find("lon 0, lat 0") != std::string::npos);
  }
}
