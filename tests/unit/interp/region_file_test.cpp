// Coastline[n].RegionFile: a shapefile's one polygon as the Region (docs/coastlines.md §4),
// written here with shapelib: the Irish Sea polygon of tests/scripts/coastline/region_polygon.geo
// gives the same two open boundaries read from a file; a file of two polygons, a
// self-crossing one, and a Region set as well are errors at the RegionFile statement.
#include <doctest/doctest.h>
#include <shapefil.h>

#include <sstream>
#include <string>
#include <vector>

#include "interp/interpreter.h"
#include "scratch_dir.h"

using namespace sm;

namespace {

// One Polygon record per ring {lon1, lat1, lon2, lat2, ...}, each written clockwise and
// closed as the shapefile format has it.
void write_region_polygons(const std::string& base, const std::vector<std::vector<double>>& rings) {
  SHPHandle h = SHPCreate(base.c_str(), SHPT_POLYGON);
  REQUIRE(h != nullptr);
  for (const auto& r : rings) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i + 1 < r.size(); i += 2) x.push_back(r[i]), y.push_back(r[i + 1]);
    double area2 = 0;   // shoelace: positive when counter-clockwise
    for (std::size_t i = 0; i < x.size(); ++i)
      area2 += x[i] * y[(i + 1) % x.size()] - x[(i + 1) % x.size()] * y[i];
    if (area2 > 0) std::reverse(x.begin(), x.end()), std::reverse(y.begin(), y.end());
    x.push_back(x.front());
    y.push_back(y.front());
    SHPObject* o = SHPCreateSimpleObject(SHPT_POLYGON, static_cast<int>(x.size()), x.data(), y.data(), nullptr);
    SHPWriteObject(h, -1, o);
    SHPDestroyObject(o);
  }
  SHPClose(h);
}

struct RegionFileRun {
  lang::SourceManager sources;
  lang::Diagnostics diags{sources};
  std::ostringstream out;
  interp::RunSettings settings;
  RegionFileRun() { settings.stdlib_dir = SM_SOURCE_DIR "/stdlib"; }
  std::string run(const std::string& script) {
    interp::Interpreter in(sources, diags, out, settings);
    in.run_buffer("region_file.geo", script);
    return out.str();
  }
};

const std::vector<double> kIrishSeaPolygon = {-5.27, 51.89, -2.2, 52.2, -2.2, 55.3, -4.5, 55.1, -5.0, 54.90,
                                       -6.10, 55.17, -7.5, 54.5, -7.5, 52.5, -6.45, 52.22};

std::string region_script(const std::string& region_lines) {
  return "R = 6371009; Point(1) = {0, 0, 0}; Point(2) = {0, 0, R}; PolarSphere(1) = {1, 2};\n"
         "Field[1] = MathEval; Field[1].F = \"2000\";\n"
         "Coastline[1] = LonLatText;\n"
         "Coastline[1].FileName = \"" SM_SOURCE_DIR "/data/gshhg/gb_ireland_f.txt\";\n"
         "Coastline[1].AccuracyField = 1;\n" +
         region_lines +
         "Coastline[1].SeaAt = {-5.4, 53.35};\n"
         "open[] = Coastline{1, \"OpenCurves\"};\n"
         "Printf(\"open %g\", #open[]);\n";
}

}  // namespace

TEST_CASE("region file: the Irish Sea polygon read from a shapefile") {
  sm::testing::ScratchDir dir;
  const std::string base = (dir.path / "irish_sea").string();
  write_region_polygons(base, {kIrishSeaPolygon});
  RegionFileRun r;
  const std::string out = r.run(region_script("Coastline[1].RegionFile = \"" + base + ".shp\";\n"));
  INFO(r.diags.render_all());
  REQUIRE(r.diags.error_count() == 0);
  CHECK(out.find("open 2") != std::string::npos);
}

TEST_CASE("region file: two polygons, a bow tie, a missing file, Region set too") {
  sm::testing::ScratchDir dir;
  const std::string two = (dir.path / "two").string(), bow = (dir.path / "bow").string();
  write_region_polygons(two, {{-6, 52, -5, 52, -5, 53}, {-4, 54, -3, 54, -3, 55}});
  // A bow tie written as one part: shapelib keeps the order, our check finds the crossing.
  SHPHandle h = SHPCreate(bow.c_str(), SHPT_POLYGON);
  REQUIRE(h != nullptr);
  double x[] = {-6, -4, -4, -6, -6}, y[] = {52, 54, 52, 54, 52};
  SHPObject* o = SHPCreateSimpleObject(SHPT_POLYGON, 5, x, y, nullptr);
  SHPWriteObject(h, -1, o);
  SHPDestroyObject(o);
  SHPClose(h);
  const struct {
    std::string lines, says, at;
  } cases[] = {
      {"Coastline[1].RegionFile = \"" + two + ".shp\";\n", "holds 2 outer ring(s)", "region_file.geo:6:1"},
      {"Coastline[1].RegionFile = \"" + bow + ".shp\";\n", "crosses itself", "region_file.geo:6:1"},
      {"Coastline[1].RegionFile = \"" + (dir.path / "none.shp").string() + "\";\n", "cannot be read",
       "region_file.geo:6:1"},
      {"Coastline[1].Region = {-6, 52, -5, 52, -5, 53};\nCoastline[1].RegionFile = \"" + two + ".shp\";\n",
       "both Region and RegionFile", "region_file.geo:7:1"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.says);
    RegionFileRun r;
    r.run(region_script(c.lines));
    const std::string diag = r.diags.render_all();
    CHECK(r.diags.error_count() == 1);
    CHECK(diag.find(c.says) != std::string::npos);
    CHECK(diag.find(c.at) != std::string::npos);   // at the RegionFile statement
  }
}

// RegionalSea (stdlib/regions.geo) passes RegionalRegionFile to Coastline's RegionFile: the
// same two open boundaries, and the shore points are the coast curves' own ("CoastPoints",
// for ShoreProximity without a ShoreBox[]); RegionalBox[] as well is an error.
std::string regional_script(const std::string& base, const std::string& extra) {
  return "Include \"earth.geo\";\nInclude \"regions.geo\";\nCall EarthSphere;\n"
         "RegionalFile = \"" SM_SOURCE_DIR "/data/gshhg/gb_ireland_f.txt\";\n"
         "RegionalRegionFile = \"" + base + ".shp\";\n" + extra +
         "RegionalAccuracy = 2e3;\nRegionalSeaAt[] = {-5.4, 53.35};\nCall RegionalSea;\n"
         "coast[] = Coastline{1, \"CoastPoints\"};\n"
         "Printf(\"open %g, shore points are CoastPoints %g\", #RegionalOpenCurves[], "
         "#RegionalShorePoints[] == #coast[] && #Unique({RegionalShorePoints[], coast[]}) == #coast[]);\n";
}

TEST_CASE("region file: RegionalSea with RegionalRegionFile") {
  sm::testing::ScratchDir dir;
  const std::string base = (dir.path / "irish_sea").string();
  write_region_polygons(base, {kIrishSeaPolygon});
  {
    RegionFileRun r;
    const std::string out = r.run(regional_script(base, ""));
    INFO(r.diags.render_all());
    REQUIRE(r.diags.error_count() == 0);
    CHECK(out.find("open 2, shore points are CoastPoints 1") != std::string::npos);
  }
  RegionFileRun r;
  r.run(regional_script(base, "RegionalBox[] = {-7, -2.5, 51.5, 55.5};\n"));
  CHECK(r.diags.error_count() == 1);
  CHECK(r.diags.render_all().find("set RegionalBox[] or RegionalRegionFile, not both") != std::string::npos);
}
