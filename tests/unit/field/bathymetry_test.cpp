#include "field/bathymetry.h"

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <doctest/doctest.h>

#include "field/error.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;
using sm::field::testing::repo_data;

namespace {

FieldSet bathy(const std::string& rel) {
  FieldSet fs;
  fs.define(1, "Bathymetry");
  fs.set(1, "FileName", repo_data("bathymetry/" + rel));
  return fs;
}

}  // namespace

// Values read with `ncdump -v z -f c etopo5_gbr_5min.nc`: z(100,150) = -1511,
// z(100,151) = -1581, z(101,150) = -1491, z(101,151) = -1496 at lon
// 152.5/152.5833, lat -17.6667/-17.5833; z(100,50) = 410 (land).
TEST_CASE("bathymetry: GBR netCDF depth at nodes and midpoints, unit and Earth spheres") {
  FieldSet fs = bathy("etopo5_gbr_5min.nc");
  const double lat0 = -26 + 100.0 / 12, lat1 = -26 + 101.0 / 12;
  CHECK(eval1(fs, 1, point_of(152.5, lat0, 1)) == doctest::Approx(1511));
  CHECK(eval1(fs, 1, point_of(152.5 + 1.0 / 12, lat1, 6371e3)) == doctest::Approx(1496));
  CHECK(eval1(fs, 1, point_of(152.5 + 1.0 / 24, (lat0 + lat1) / 2, 1)) ==
        doctest::Approx((1511 + 1581 + 1491 + 1496) / 4.0));
  CHECK(eval1(fs, 1, point_of(152.5 + 1.0 / 48, lat0, 1)) == doctest::Approx(0.75 * 1511 + 0.25 * 1581));
  CHECK(eval1(fs, 1, point_of(140 + 50.0 / 12, lat0, 1)) == 10);  // land: MinDepth
  fs.set(1, "MinDepth", 0.5);
  CHECK(eval1(fs, 1, point_of(140 + 50.0 / 12, lat0, 1)) == 0.5);
  fs.set(1, "Positive", std::string("down"));  // values taken as depths: 410 m
  CHECK(eval1(fs, 1, point_of(140 + 50.0 / 12, lat0, 1)) == doctest::Approx(410));
}

TEST_CASE("bathymetry: the ESRI ASCII grids equal the netCDF ones (first row north)") {
  for (const char* base : {"etopo5_gbr_5min", "etopo5_global_1deg", "etopo5_nw_europe_5min"}) {
    const LonLatGrid nc = read_netcdf_grid(repo_data(std::string("bathymetry/") + base + ".nc"), {});
    const LonLatGrid asc = read_esri_ascii_grid(repo_data(std::string("bathymetry/") + base + ".asc"));
    REQUIRE(asc.nlon == nc.nlon);
    REQUIRE(asc.nlat == nc.nlat);
    CHECK(asc.lon0 == doctest::Approx(nc.lon0));
    CHECK(asc.lat0 == doctest::Approx(nc.lat0));
    for (std::size_t k = 0; k < nc.v.size(); k += 97) CHECK(asc.v[k] == doctest::Approx(nc.v[k]).epsilon(1e-6));
  }
}

// ncdump of etopo5_global_1deg.nc: z(90,359) = -5216.686 (lon 179, lat 0),
// z(90,0) = -5227.628 (lon -180), z(91,359) = -5317.409, z(91,0) = -5261.226.
TEST_CASE("bathymetry: the +-180 wrap on the global grid, and the poles") {
  FieldSet fs = bathy("etopo5_global_1deg.nc");
  const double mid = (5216.686 + 5227.628 + 5317.409 + 5261.226) / 4;
  CHECK(eval1(fs, 1, point_of(179.5, 0.5, 1)) == doctest::Approx(mid));
  CHECK(eval1(fs, 1, point_of(-180.5, 0.5, 1)) == doctest::Approx(mid));
  CHECK(eval1(fs, 1, point_of(180, 0, 1)) == doctest::Approx(5227.628));
  // At a pole every longitude gives the same value (the grid row at 90N).
  const double np = eval1(fs, 1, {0, 0, 1});
  CHECK(eval1(fs, 1, point_of(77, 90, 1)) == doctest::Approx(np));
  CHECK(std::isfinite(eval1(fs, 1, {0, 0, -1})));
}

// ncdump of etopo60.cdf: ETOPO60X = 20.5 .. 379.5, ETOPO60Y(90) = 0.5,
// ROSE(90,0) = 394.75, ROSE(90,359) = 393.5833 (lon 379.5 = 19.5E),
// ROSE(90,339) = -4953.229 (lon 359.5), ROSE(91,339) = -4951.188.
TEST_CASE("bathymetry: the Ferret etopo60.cdf (lon 20.5..379.5, ROSE variable)") {
  FieldSet fs = bathy("etopo60.cdf");
  fs.set(1, "Positive", std::string("down"));  // keep the raw elevation sign
  fs.set(1, "MinDepth", -1e9);
  CHECK(eval1(fs, 1, point_of(20, 0.5, 1)) == doctest::Approx((394.75 + 393.5833) / 2));
  CHECK(eval1(fs, 1, point_of(-0.5, 1.0, 1)) == doctest::Approx((-4953.229 - 4951.188) / 2));
  fs.set(1, "ZVariable", std::string("ROSE"));
  fs.set(1, "LonVariable", std::string("ETOPO60X"));
  fs.set(1, "LatVariable", std::string("ETOPO60Y"));
  CHECK(eval1(fs, 1, point_of(359.5, 0.5, 1)) == doctest::Approx(-4953.229));
}

TEST_CASE("bathymetry: f1, the gravity-wave wavelength criterion") {
  FieldSet fs = bathy("etopo5_gbr_5min.nc");
  fs.set(1, "Output", std::string("wavelength"));
  fs.set(1, "WaveLengthMin", 100e3);
  fs.set(1, "PointsPerWaveLength", 10.0);
  fs.set(1, "DepthRef", 4000.0);
  const double lat0 = -26 + 100.0 / 12;
  CHECK(eval1(fs, 1, point_of(152.5, lat0, 1)) == doctest::Approx(1e4 * std::sqrt(4000 / 1511.0)));
  CHECK(eval1(fs, 1, point_of(140 + 50.0 / 12, lat0, 1)) == doctest::Approx(1e4 * std::sqrt(400.0)));
}

TEST_CASE("bathymetry: f2 of the Hessian on the sphere, exact on quadratics") {
  const double r = 6371e3, deg = 3.141592653589793 / 180;
  LonLatGrid g;
  g.nlon = 41;
  g.nlat = 41;
  g.lon0 = -10;
  g.lat0 = -10;
  g.dlon = g.dlat = 0.5;
  g.v.resize(41 * 41);
  // Depth/H_ref = 1 + c phi^2: the north-north second derivative is 2c/R^2 at
  // the equator, everything else vanishes there.
  const double c = 50;
  for (int j = 0; j < 41; ++j)
    for (int i = 0; i < 41; ++i) g.at(i, j) = 2000 * (1 + c * std::pow(g.lat(j) * deg, 2));
  LonLatGrid f2 = hessian_criterion(g, 2000, r);
  CHECK(f2.at(20, 20) == doctest::Approx(r / std::sqrt(2 * c)).epsilon(1e-6));
  // Depth/H_ref = 1 + c lambda^2 along a parallel at 60N: east-east term
  // 2c/(R cos 60)^2 at lambda = 0.
  g.lat0 = 50;
  for (int j = 0; j < 41; ++j)
    for (int i = 0; i < 41; ++i) g.at(i, j) = 2000 * (1 + c * std::pow(g.lon(i) * deg, 2));
  f2 = hessian_criterion(g, 2000, r);
  CHECK(f2.at(20, 20) == doctest::Approx(r * 0.5 / std::sqrt(2 * c)).epsilon(1e-6));
  // A plane has no curvature: no constraint.
  for (double& v : g.v) v = 1234;
  f2 = hessian_criterion(g, 2000, r);
  CHECK(f2.at(20, 20) == 1e22);
}

TEST_CASE("bathymetry: f2 on the real GBR grid is positive and finer over the shelf break") {
  FieldSet fs = bathy("etopo5_gbr_5min.nc");
  fs.set(1, "Output", std::string("hessian"));
  fs.set(1, "DepthRef", 100.0);
  // Coral Sea abyss (flat, 155E 20S) against the shelf break off Cairns (146.5E 16.5S).
  const double abyss = eval1(fs, 1, point_of(155, -20, 1));
  const double shelf = eval1(fs, 1, point_of(146.5, -16.5, 1));
  CHECK(shelf > 0);
  CHECK(shelf < abyss);
}

TEST_CASE("bathymetry: bad input is rejected with typed, located errors") {
  FieldSet fs = bathy("no_such_file.nc");
  try {
    fs.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(e.field_id == 1);
    CHECK(e.file.find("no_such_file.nc") != std::string::npos);
  }
  FieldSet var = bathy("etopo5_gbr_5min.nc");
  var.set(1, "ZVariable", std::string("depth"));
  try {
    var.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(std::string(e.what()).find("no variable 'depth' (variables: lon, lat, z)") != std::string::npos);
  }
  FieldSet out = bathy("etopo5_gbr_5min.nc");
  out.set(1, "Output", std::string("curl"));
  CHECK_THROWS_AS(out.build(1, {}), FieldError);
  FieldSet pos = bathy("etopo5_gbr_5min.nc");
  pos.set(1, "Positive", std::string("sideways"));
  CHECK_THROWS_AS(pos.build(1, {}), FieldError);
  FieldSet md = bathy("etopo5_gbr_5min.nc");
  md.set(1, "Output", std::string("wavelength"));
  md.set(1, "MinDepth", 0.0);
  CHECK_THROWS_AS(md.build(1, {}), FieldError);
  // A grid with a missing node: an error naming its lon/lat, unless MissingAsLand.
  const auto dir = std::filesystem::temp_directory_path() / ("sm_field_bathy_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto asc = dir / "hole.asc";
  {
    std::ofstream o(asc);
    o << "ncols 3\nnrows 2\nxllcorner 10\nyllcorner 20\ncellsize 1\nNODATA_value -9999\n"
      << "-100 -200 -300\n-400 -9999 -600\n";
  }
  FieldSet hole;
  hole.define(1, "Bathymetry");
  hole.set(1, "FileName", asc.string());
  try {
    hole.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(std::string(e.what()).find("lon 11.5, lat 20.5") != std::string::npos);
  }
  hole.set(1, "MissingAsLand", 1.0);
  CHECK(eval1(hole, 1, point_of(11.5, 20.5, 1)) == doctest::Approx(10));
  CHECK(eval1(hole, 1, point_of(10.5, 21.5, 1)) == doctest::Approx(100));
  {
    std::ofstream o(asc);
    o << "ncols 3\nnrows 2\nxllcorner 10\nyllcorner 20\ncellsize 1\n-100 -200 -300\n-400\n";
  }
  hole.set(1, "MissingAsLand", 0.0);
  CHECK_THROWS_AS(hole.build(1, {}), FieldError);
  std::filesystem::remove_all(dir);
}

// Every relief file of the shared data set reads, with the value ranges its
// README gives (and the Ferret files' wrap columns detected).
TEST_CASE("bathymetry: all shared netCDF grids read with their documented ranges") {
  struct Case {
    const char* file;
    int nlon, nlat;
    double lo, hi;
    int period;
  };
  const Case cases[] = {
      {"etopo5_global_0.25deg.nc", 1441, 721, -9565.2, 6324.2, 1440},
      {"etopo5_global_1deg.nc", 361, 181, -7733.8, 5669.1, 360},
      {"etopo5_nw_europe_5min.nc", 265, 181, -4834, 2248, 0},
      {"etopo5_gbr_5min.nc", 193, 205, -4834, 3052, 0},
      {"etopo5_canadian_arctic_5min.nc", 1081, 361, -3853, 3205, 0},
      {"etopo60.cdf", 360, 180, -1e9, 1e9, 360},
      {"etopo20.cdf", 1081, 540, -1e9, 1e9, 1080},
  };
  for (const Case& c : cases) {
    CAPTURE(c.file);
    const LonLatGrid g = read_netcdf_grid(repo_data(std::string("bathymetry/") + c.file), {});
    CHECK(g.nlon == c.nlon);
    CHECK(g.nlat == c.nlat);
    CHECK(g.period == c.period);
    double lo = 1e300, hi = -1e300;
    std::size_t non_finite = 0;
    for (double v : g.v) {
      if (!std::isfinite(v)) ++non_finite;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    CHECK(non_finite == 0);
    if (c.lo > -1e9) {
      CHECK(lo == doctest::Approx(c.lo).epsilon(1e-4));
      CHECK(hi == doctest::Approx(c.hi).epsilon(1e-4));
    }
    CHECK(lo < -3000);
    CHECK(hi > 2000);
  }
}

// A finite but absurd scale_factor (1e300: reliefs of -1e302 m) passes the reader's
// checks (finite, non-zero) and is caught as a relief no Earth has.
TEST_CASE("bathymetry: a relief beyond 1000 km is an error naming the file and the node") {
  FieldSet fs;
  fs.define(1, "Bathymetry");
  const std::string file = std::string(SM_TEST_DATA) + "/grids/scale_1e300.nc";
  fs.set(1, "FileName", file);
  try {
    fs.build(1, {});
    FAIL("built");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(e.field_id == 1);
    CHECK(std::string(e.what()).find(file + ": relief -1e+302 m at lon 0, lat 40") != std::string::npos);
  }
  fs.set(1, "FileName", std::string(SM_TEST_DATA) + "/grids/small.nc");
  CHECK(eval1(fs, 1, point_of(8, 46, 1)) == doctest::Approx(960));
}

TEST_CASE("bathymetry: the tidal wavelength T sqrt(g H) / N, finer where shallower") {
  FieldSet fs = bathy("etopo5_gbr_5min.nc");
  fs.set(1, "Output", std::string("tidal"));
  fs.set(1, "PointsPerWaveLength", 50.0);
  const double lat0 = -26 + 100.0 / 12;
  // Node z(100,150) = -1511 m; a land node reads MinDepth (10 m).
  CHECK(eval1(fs, 1, point_of(152.5, lat0, 1)) == doctest::Approx(44712 * std::sqrt(9.81 * 1511) / 50));
  CHECK(eval1(fs, 1, point_of(140 + 50.0 / 12, lat0, 1)) == doctest::Approx(44712 * std::sqrt(9.81 * 10) / 50));
  fs.set(1, "Period", 86164.0);   // K1
  CHECK(eval1(fs, 1, point_of(152.5, lat0, 1)) == doctest::Approx(86164 * std::sqrt(9.81 * 1511) / 50));
  fs.set(1, "Period", 0.0);
  CHECK_THROWS_AS(eval1(fs, 1, point_of(152.5, lat0, 1)), FieldError);
}

TEST_CASE("bathymetry: the slope criterion (2 pi / N) H / |grad H| on the sphere") {
  const double r = 6371e3, deg = 3.141592653589793 / 180;
  LonLatGrid g;
  g.nlon = 41;
  g.nlat = 41;
  g.lon0 = -10;
  g.lat0 = 50;
  g.dlon = g.dlat = 0.5;
  g.v.resize(41 * 41);
  // H = 1000 + a * R * lat (radians): |grad H| = a northward, exact for centred
  // differences; along a parallel at 60N, H = 1000 + a R cos(60) lon: |grad H| = a east.
  const double a = 1e-3;
  for (int j = 0; j < 41; ++j)
    for (int i = 0; i < 41; ++i) g.at(i, j) = 1000 + a * r * (g.lat(j) - 60) * deg;
  LonLatGrid s = slope_criterion(g, 10, r);
  CHECK(s.at(20, 20) == doctest::Approx(2 * 3.141592653589793 / 10 * 1000 / a).epsilon(1e-9));
  for (int j = 0; j < 41; ++j)
    for (int i = 0; i < 41; ++i) g.at(i, j) = 1000 + a * r * 0.5 * g.lon(i) * deg;
  s = slope_criterion(g, 10, r);
  CHECK(s.at(20, 20) == doctest::Approx(2 * 3.141592653589793 / 10 * 1000 / a).epsilon(1e-9));
  for (double& v : g.v) v = 1234;
  CHECK(slope_criterion(g, 10, r).at(20, 20) == 1e22);
  // On the real grid through the kind: positive, finite somewhere, MinDepth required.
  FieldSet fs = bathy("etopo5_gbr_5min.nc");
  fs.set(1, "Output", std::string("slope"));
  fs.set(1, "PointsPerWaveLength", 10.0);
  fs.set(1, "Radius", 1.0);
  const double v = eval1(fs, 1, point_of(152.5, -26 + 100.0 / 12, 1));
  CHECK(v > 0);
  CHECK(v < 1e22);
  fs.set(1, "MinDepth", 0.0);
  CHECK_THROWS_AS(eval1(fs, 1, point_of(152.5, -18, 1)), FieldError);
}

TEST_CASE("time step field: Dt sqrt(g H) / Courant from a depth field or a grid") {
  FieldSet fs;
  fs.define(1, "MathEval");
  fs.set(1, "F", std::string("100 * x"));
  fs.define(2, "TimeStep");
  fs.set(2, "DepthField", 1.0);
  fs.set(2, "Dt", 30.0);
  CHECK(eval1(fs, 2, {40, 0, 0}) == doctest::Approx(30 * std::sqrt(9.81 * 4000)));
  CHECK(eval1(fs, 2, {0, 0, 0}) == doctest::Approx(30 * std::sqrt(9.81 * 10)));   // MinDepth 10
  fs.set(2, "Courant", 0.5);
  CHECK(eval1(fs, 2, {40, 0, 0}) == doctest::Approx(60 * std::sqrt(9.81 * 4000)));
  FieldSet grid;
  grid.define(1, "TimeStep");
  grid.set(1, "FileName", repo_data("bathymetry/etopo5_gbr_5min.nc"));
  grid.set(1, "Dt", 10.0);
  CHECK(eval1(grid, 1, point_of(152.5, -26 + 100.0 / 12, 1)) == doctest::Approx(10 * std::sqrt(9.81 * 1511)));
  grid.set(1, "Dt", 0.0);
  CHECK_THROWS_AS(eval1(grid, 1, point_of(152.5, -18, 1)), FieldError);
  grid.set(1, "Dt", 10.0);
  grid.set(1, "DepthField", 1.0);   // both
  CHECK_THROWS_AS(eval1(grid, 1, point_of(152.5, -18, 1)), FieldError);
}
