// LonLat (with Gmsh 4.8.4's quirks) and Param.
#include <cmath>
#include <numbers>

#include <doctest/doctest.h>

#include "field/lonlat_grid.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

TEST_CASE("lonlat: Field[InField](lon, lat, 0) in radians, latitude from RadiusStereo") {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("0.02 + 0.1*(Pi/2 - y) + 1000*z + 0*x"));
  fs.define(2, "LonLat");
  fs.set(2, "IField", 1.0);
  fs.set(2, "RadiusStereo", 1.0);
  const Vec3 p = point_of(30, 45, 1);
  CHECK(eval1(fs, 2, p) == doctest::Approx(0.02 + 0.1 * std::numbers::pi / 4));
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("x"));
  fs.define(4, "LonLat");
  fs.set(4, "InField", 3.0);
  fs.set(4, "RadiusStereo", 1.0);
  CHECK(eval1(fs, 4, point_of(-120, 10, 1)) == doctest::Approx(-120 * std::numbers::pi / 180));
  // The quirk: on a sphere of radius 2 with RadiusStereo 1, lat = asin(z/1).
  fs.define(5, "MathEval");
  fs.set(5, "F", std::string("y"));
  fs.define(6, "LonLat");
  fs.set(6, "InField", 5.0);
  fs.set(6, "RadiusStereo", 1.0);
  CHECK(eval1(fs, 6, point_of(0, 10, 2)) == doctest::Approx(std::asin(2 * std::sin(10 * std::numbers::pi / 180))));
  CHECK(std::isnan(eval1(fs, 6, point_of(0, 60, 2))));
}

TEST_CASE("lonlat: FromStereo maps 2R stereographic coordinates back to the sphere") {
  const double r = 6371e3;
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("y"));
  fs.define(2, "LonLat");
  fs.set(2, "InField", 1.0);
  fs.set(2, "FromStereo", 1.0);
  const Vec3 s = point_of(40, -20, r);
  // xi = 2R x/(R + z), eta = 2R y/(R + z)
  const Vec3 stereo{2 * r * s.x / (r + s.z), 2 * r * s.y / (r + s.z), 12345};
  CHECK(eval1(fs, 2, stereo) == doctest::Approx(-20 * std::numbers::pi / 180));
  fs.set(1, "F", std::string("x"));
  CHECK(eval1(fs, 2, stereo) == doctest::Approx(40 * std::numbers::pi / 180));
}

TEST_CASE("param: Field[InField] at (FX, FY, FZ)") {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("100*x + 10*y + z"));
  fs.define(2, "Param");
  fs.set(2, "IField", 1.0);
  fs.set(2, "FX", std::string("y"));
  fs.set(2, "FY", std::string("x^2"));
  CHECK(eval1(fs, 2, {3, 2, 5}) == 200 + 90 + 5);
  fs.set(2, "FZ", std::string("F1"));
  CHECK_THROWS(fs.build(2, {}));
}
