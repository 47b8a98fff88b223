// Bathymetry with Output "depth": cell averaging at mesh nodes, grids by priority, the
// MinDepth account, and the units / reference-system checks of a list of grids. The
// grids are written here with libnetcdf, small enough to compute by hand.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include <netcdf.h>

#include "field/bathymetry.h"
#include "field/error.h"
#include "field/field_set.h"

using namespace sm;
using namespace sm::field;

namespace {



struct DepthGridSpec {
  double lon0, dlon;
  int nlon;
  double lat0, dlat;
  int nlat;
  std::function<double(double lon, double lat)> z;   // NaN: _FillValue
  std::string units = "m";
  std::string crs;                                     // grid_mapping's crs_wkt, "" for none
};

// Writes z(lat, lon) as doubles with _FillValue -99999.
void write_depth_grid(const std::filesystem::path& file, const DepthGridSpec& g) {
  int nc, dlon, dlat, vlon, vlat, vz;
  REQUIRE(nc_create(file.c_str(), NC_CLOBBER, &nc) == NC_NOERR);
  REQUIRE(nc_def_dim(nc, "lon", static_cast<std::size_t>(g.nlon), &dlon) == NC_NOERR);
  REQUIRE(nc_def_dim(nc, "lat", static_cast<std::size_t>(g.nlat), &dlat) == NC_NOERR);
  REQUIRE(nc_def_var(nc, "lon", NC_DOUBLE, 1, &dlon, &vlon) == NC_NOERR);
  REQUIRE(nc_def_var(nc, "lat", NC_DOUBLE, 1, &dlat, &vlat) == NC_NOERR);
  const int dims[2] = {dlat, dlon};
  REQUIRE(nc_def_var(nc, "z", NC_DOUBLE, 2, dims, &vz) == NC_NOERR);
  nc_put_att_text(nc, vlon, "units", 12, "degrees_east");
  nc_put_att_text(nc, vlat, "units", 13, "degrees_north");
  const double fill = -99999;
  nc_put_att_double(nc, vz, "_FillValue", NC_DOUBLE, 1, &fill);
  if (!g.units.empty()) nc_put_att_text(nc, vz, "units", g.units.size(), g.units.c_str());
  if (!g.crs.empty()) {
    int vc;
    REQUIRE(nc_def_var(nc, "crs", NC_INT, 0, nullptr, &vc) == NC_NOERR);
    nc_put_att_text(nc, vc, "crs_wkt", g.crs.size(), g.crs.c_str());
    nc_put_att_text(nc, vz, "grid_mapping", 3, "crs");
  }
  REQUIRE(nc_enddef(nc) == NC_NOERR);
  std::vector<double> lon(static_cast<std::size_t>(g.nlon)), lat(static_cast<std::size_t>(g.nlat));
  for (int i = 0; i < g.nlon; ++i) lon[static_cast<std::size_t>(i)] = g.lon0 + i * g.dlon;
  for (int j = 0; j < g.nlat; ++j) lat[static_cast<std::size_t>(j)] = g.lat0 + j * g.dlat;
  std::vector<double> z;
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i) {
      const double v = g.z(lon[static_cast<std::size_t>(i)], lat[static_cast<std::size_t>(j)]);
      z.push_back(std::isnan(v) ? fill : v);
    }
  REQUIRE(nc_put_var_double(nc, vlon, lon.data()) == NC_NOERR);
  REQUIRE(nc_put_var_double(nc, vlat, lat.data()) == NC_NOERR);
  REQUIRE(nc_put_var_double(nc, vz, z.data()) == NC_NOERR);
  REQUIRE(nc_close(nc) == NC_NOERR);
}

struct DepthTmp {
  std::filesystem::path dir;
  DepthTmp() {
    dir = std::filesystem::temp_directory_path() / ("sm_depth_grids_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
  }
  ~DepthTmp() { std::filesystem::remove_all(dir); }
};

const GridDepthField& depth_field(const BuiltFields& b) {
  const auto* f = dynamic_cast<const GridDepthField*>(b.get(1));
  REQUIRE(f != nullptr);
  return *f;
}

Vec3 depth_on_unit(double lon, double lat) { return point_of(lon, lat, 1); }
constexpr double kDepthDeg = std::numbers::pi / 180;

}  // namespace

TEST_CASE("depth grids: the cell mean within half the local size, by hand") {
  DepthTmp tmp;
  // Depth 10 i + j at lon i, lat j (degrees), Positive "down".
  write_depth_grid(tmp.dir / "g.nc",
                   {0, 1, 10, 0, 1, 10, [](double lon, double lat) { return 10 * lon + lat; }, "m", ""});
  FieldSet fs;
  fs.define(1, "Bathymetry");
  fs.set(1, "FileName", (tmp.dir / "g.nc").string());
  fs.set(1, "Positive", std::string("down"));
  fs.set(1, "MinDepth", 1.0);
  const BuiltFields b = fs.build(1, {});
  const GridDepthField& f = depth_field(b);
  const std::vector<Vec3> p{depth_on_unit(4.2, 4.3)};
  std::vector<double> out(1);
  // Cell centres within 1.25 degrees of (4.2, 4.3): distances (cos 4.3 = 0.99719)
  // (4,4) 0.360, (5,4) 0.852, (4,5) 0.728, (5,5) 1.061, (3,4) 1.234; out: (3,5) 1.386,
  // (4,3) 1.315. Mean of 44, 54, 45, 55, 34 = 46.4.
  const std::vector<double> r{1.25 * kDepthDeg};
  DepthClampReport rep;
  f.node_depths(p, r, out, &rep);
  CHECK(out[0] == doctest::Approx(46.4));
  CHECK(rep.clamped == 0);
  // 1.2 degrees leaves (3,4) out: (44 + 54 + 45 + 55) / 4.
  f.node_depths(p, std::vector<double>{1.2 * kDepthDeg}, out, nullptr);
  CHECK(out[0] == doctest::Approx(49.5));
  // No centre within 0.1 degree: the nearest cell, (4,4).
  f.node_depths(p, std::vector<double>{0.1 * kDepthDeg}, out, nullptr);
  CHECK(out[0] == 44);
  // Without sizes: the bilinear value, as eval gives it (exact on a linear grid).
  f.node_depths(p, {}, out, nullptr);
  CHECK(out[0] == doctest::Approx(46.3));
  std::vector<double> ev(1);
  f.eval(p, ev);
  CHECK(ev[0] == out[0]);

  // MinDepth above the mean: raised, and said where and from what.
  fs.set(1, "MinDepth", 47.0);
  const BuiltFields b2 = fs.build(1, {});
  depth_field(b2).node_depths(p, r, out, &rep);
  CHECK(out[0] == 47);
  CHECK(rep.points == 1);
  CHECK(rep.clamped == 1);
  CHECK(rep.has_worst);
  CHECK(rep.lon == doctest::Approx(4.2));
  CHECK(rep.lat == doctest::Approx(4.3));
  CHECK(rep.grid_depth == doctest::Approx(46.4));
  CHECK(rep.value == 47);
  CHECK(rep.dry == 0);

  // The same values as elevations: land, 46.4 m high in the mean, raised to 1 m.
  fs.set(1, "Positive", std::string("up"));
  fs.set(1, "MinDepth", 1.0);
  const BuiltFields b3 = fs.build(1, {});
  depth_field(b3).node_depths(p, r, out, &rep);
  CHECK(out[0] == 1);
  CHECK(rep.clamped == 1);
  CHECK(rep.dry == 1);
  CHECK(rep.grid_depth == doctest::Approx(-46.4));
}

TEST_CASE("depth grids: half the mean incident edge, each edge once") {
  // Three nodes on the unit sphere: 0-1 is 2 degrees, 0-2 is 4 degrees; 0-1 twice.
  const std::vector<Vec3> xyz{depth_on_unit(0, 0), depth_on_unit(2, 0), depth_on_unit(0, 4)};
  const std::vector<double> h = half_edge_angles(xyz, {{0, 1}, {1, 0}, {2, 0}});
  CHECK(h[0] == doctest::Approx(0.5 * 3 * kDepthDeg));
  CHECK(h[1] == doctest::Approx(1 * kDepthDeg));
  CHECK(h[2] == doctest::Approx(2 * kDepthDeg));
  CHECK(half_edge_angles(xyz, {})[1] == 0);
}

TEST_CASE("depth grids: the finest grid that covers a point wins, the next fills its gaps") {
  DepthTmp tmp;
  // Coarse: 1000 + lon over lon, lat 0..20 every 2 degrees. Fine: 50 over 5..10 every
  // 0.5 degree, missing at (6.5, 6.5).
  write_depth_grid(tmp.dir / "coarse.nc", {0, 2, 11, 0, 2, 11, [](double lon, double) { return 1000 + lon; }, "m", ""});
  write_depth_grid(tmp.dir / "fine.nc", {5, 0.5, 11, 5, 0.5, 11, [](double lon, double lat) {
                     return lon == 6.5 && lat == 6.5 ? std::nan("") : 50.0;
                   }, "m", ""});
  FieldSet fs;
  fs.define(1, "Bathymetry");
  fs.set(1, "FileName", (tmp.dir / "fine.nc").string() + ", " + (tmp.dir / "coarse.nc").string());
  fs.set(1, "Positive", std::string("down"));
  const BuiltFields b = fs.build(1, {});
  const GridDepthField& f = depth_field(b);
  const std::vector<Vec3> p{depth_on_unit(5.6, 5.6), depth_on_unit(15, 15), depth_on_unit(6.75, 6.75),
                            depth_on_unit(4.9, 7), depth_on_unit(8, 8)};
  std::vector<double> out(p.size());
  f.eval(p, out);
  CHECK(out[0] == 50);                            // inside the fine grid
  CHECK(out[1] == doctest::Approx(1015));         // outside it
  CHECK(out[2] == doctest::Approx(1006.75));      // a corner is missing
  CHECK(out[3] == doctest::Approx(1004.9));       // just west of it
  CHECK(out[4] == 50);
  // Cell means: at the missing node with a small size, its nearest cell is missing, so
  // the coarse grid's nearest (6, 6) answers; with 0.6 degree the fine cells around it.
  const std::vector<Vec3> q{depth_on_unit(6.5, 6.5)};
  std::vector<double> one(1);
  f.node_depths(q, std::vector<double>{0.1 * kDepthDeg}, one, nullptr);
  CHECK(one[0] == 1006);
  f.node_depths(q, std::vector<double>{0.6 * kDepthDeg}, one, nullptr);
  CHECK(one[0] == 50);
  // Swapped priority: the coarse grid covers everything. The fine grid has the last
  // word on nothing, but its missing value is refused unless taken as land.
  fs.set(1, "FileName", (tmp.dir / "coarse.nc").string() + "," + (tmp.dir / "fine.nc").string());
  CHECK_THROWS_AS(fs.build(1, {}), FieldError);
  fs.set(1, "MissingAsLand", 1.0);
  const BuiltFields b2 = fs.build(1, {});
  depth_field(b2).eval(p, out);
  CHECK(out[0] == doctest::Approx(1005.6));
}

TEST_CASE("depth grids: a list of grids must share units and reference system") {
  DepthTmp tmp;
  auto flat = [](double, double) { return 100.0; };
  write_depth_grid(tmp.dir / "m.nc", {0, 1, 5, 0, 1, 5, flat, "metres", ""});
  write_depth_grid(tmp.dir / "m2.nc", {0, 1, 5, 0, 1, 5, flat, "m", ""});
  write_depth_grid(tmp.dir / "km.nc", {0, 2, 5, 0, 2, 5, flat, "km", ""});
  write_depth_grid(tmp.dir / "wgs.nc", {0, 2, 5, 0, 2, 5, flat, "m", "GEOGCS[\"WGS 84\"]"});
  write_depth_grid(tmp.dir / "ed50.nc", {0, 1, 5, 0, 1, 5, flat, "m", "GEOGCS[\"ED50\"]"});
  FieldSet fs;
  fs.define(1, "Bathymetry");
  fs.set(1, "Positive", std::string("down"));
  auto list = [&](const char* a, const char* b) { return (tmp.dir / a).string() + "," + (tmp.dir / b).string(); };
  fs.set(1, "FileName", list("m.nc", "m2.nc"));
  CHECK_NOTHROW(fs.build(1, {}));
  fs.set(1, "FileName", list("m.nc", "km.nc"));
  try {
    fs.build(1, {});
    FAIL("units m and km accepted");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::BadValue);
    CHECK(e.option == "FileName");
    CHECK(std::string(e.what()).find("'km'") != std::string::npos);
  }
  fs.set(1, "FileName", list("ed50.nc", "wgs.nc"));
  CHECK_THROWS_AS(fs.build(1, {}), FieldError);
  fs.set(1, "FileName", list("m.nc", "wgs.nc"));   // one says nothing: no conflict
  CHECK_NOTHROW(fs.build(1, {}));
  // Other outputs read one grid.
  fs.set(1, "Output", std::string("tidal"));
  CHECK_THROWS_AS(fs.build(1, {}), FieldError);
}

TEST_CASE("depth grids: a window reads only the box of the grid, with the same values") {
  DepthTmp tmp;
  write_depth_grid(tmp.dir / "g.nc",
                   {0, 1, 10, 0, 1, 10, [](double lon, double lat) { return 10 * lon + lat; }, "m", ""});
  NetcdfGridSpec spec;
  spec.window = {2.5, 5.5, 3.2, 6.8};
  // Columns lon 2..6 and rows lat 3..7 meet the box; one more on each side.
  const LonLatGrid w = read_netcdf_grid(tmp.dir / "g.nc", spec);
  CHECK(w.nlon == 7);
  CHECK(w.nlat == 7);
  CHECK(w.lon0 == 1);
  CHECK(w.lat0 == 2);
  CHECK(w.at(0, 0) == 12);
  CHECK(w.at(6, 6) == 78);
  // The field with the window gives the values of the whole grid inside the box.
  FieldSet fs;
  fs.define(1, "Bathymetry");
  fs.set(1, "FileName", (tmp.dir / "g.nc").string());
  fs.set(1, "Positive", std::string("down"));
  const std::vector<Vec3> p{depth_on_unit(4.2, 4.3), depth_on_unit(2.6, 6.7)};
  std::vector<double> whole(2), boxed(2);
  fs.build(1, {}).get(1)->eval(p, whole);
  fs.set(1, "Window", std::vector<double>{2.5, 5.5, 3.2, 6.8});
  fs.build(1, {}).get(1)->eval(p, boxed);
  CHECK(boxed[0] == whole[0]);
  CHECK(boxed[1] == whole[1]);
  // A box beside the grid, or upside down, is an error.
  fs.set(1, "Window", std::vector<double>{20, 30, 3, 6});
  CHECK_THROWS_AS(fs.build(1, {}), FieldError);
  fs.set(1, "Window", std::vector<double>{2, 5, 6, 3});
  CHECK_THROWS_AS(fs.build(1, {}), FieldError);
}
