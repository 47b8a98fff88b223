// The open-boundary curves that close a regional model along its lon/lat box follow the
// box's parallels and meridians within the coastline accuracy gamma (the box sides src/coast/region.cpp
// makes): measured on the model curves themselves, densely sampled, for
// the Irish Sea tutorial's box and the North Sea / Scheldt file's box.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "geo/sphere.h"
#include "interp/interpreter.h"

using namespace sm;

namespace {

struct Deviation {
  double max_deg = 0;     // largest distance from the box edge, degrees of lat or lon
  double max_m = 0;       // the same in metres on the sphere
  geo::LonLat where{0, 0};   // where it is largest
  std::size_t curves = 0;
};

// Runs `script` (which must Printf the open curves' tags, one per line, among its output) and measures how
// far those curves stray from the box {west, east, south, north}.
Deviation measure(const std::string& script, const double box[4]) {
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream out;
  interp::RunSettings settings;
  settings.stdlib_dir = SM_SOURCE_DIR "/stdlib";
  interp::Interpreter in(sources, diags, out, settings);
  in.run_buffer(SM_SOURCE_DIR "/examples/box_test.geo", script);
  INFO(diags.render_all());
  REQUIRE(diags.error_count() == 0);
  const geo::Model& model = in.kernel().model;
  const auto& [gtag, g] = *model.geometries().begin();
  const geo::PolarSphere sphere(g.centre(), g.radius());
  Deviation d;
  // The tags are the lines that are a whole number (the script may print more).
  std::vector<int> tag_list;
  std::istringstream lines(out.str());
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line.find_first_not_of("0123456789") == std::string::npos) tag_list.push_back(std::stoi(line));
  for (const int tag : tag_list) {
    const geo::ModelCurve* c = model.curve(tag);
    REQUIRE(c);
    ++d.curves;
    for (int k = 0; k <= 2000; ++k) {
      const geo::LonLat ll = sphere.to_lonlat(c->shape->point(k / 2000.0));
      // Distance to the nearest box edge: a parallel (lat) or a meridian (lon, scaled by
      // cos(lat) for metres).
      const double dlat = std::min(std::abs(ll.lat - box[2]), std::abs(ll.lat - box[3]));
      const double dlon = std::min(std::abs(ll.lon - box[0]), std::abs(ll.lon - box[1]));
      const double kDeg = 3.14159265358979323846 / 180;
      const double m_lat = dlat * kDeg * g.radius(), m_lon = dlon * kDeg * g.radius() * std::cos(ll.lat * kDeg);
      if (m_lat <= m_lon) {
        d.max_deg = std::max(d.max_deg, dlat);
        if (m_lat > d.max_m) d.where = ll;
        d.max_m = std::max(d.max_m, m_lat);
      } else {
        if (m_lon > d.max_m) d.where = ll;
        d.max_deg = std::max(d.max_deg, dlon);
        d.max_m = std::max(d.max_m, m_lon);
      }
    }
  }
  return d;
}

}  // namespace

TEST_CASE("region box: the Irish Sea tutorial's open curves follow the box within gamma") {
  const double box[4] = {-7, -2.5, 51.5, 55.5};
  for (double gamma : {2e3, 20e3}) {
    CAPTURE(gamma);
    const Deviation d =
        measure("CoastSize = " + std::to_string(gamma) + "; FarSize = 60e3" +
                    "; Include \"irish_sea.geo\";\n"
                    "For i In {0 : #RegionalOpenCurves[] - 1}  Printf(\"%g\", RegionalOpenCurves[i]);  EndFor\n",
                box);
    CHECK(d.curves > 0);
    MESSAGE("gamma ", gamma, " m: ", d.curves, " open curves, max deviation ", d.max_m, " m (", d.max_deg, " deg) at ",
            d.where.lon, " ", d.where.lat);
    CHECK(d.max_m < 0.05 * gamma);   // was 668 m at 2 km, 10.5 km at 20 km (B-splines cutting the corners)
  }
}

TEST_CASE("region box: the North Sea / Scheldt file box") {
  const double box[4] = {-4, 9, 48, 58};
  const Deviation d = measure("R = 6371009; Point(1) = {0, 0, 0}; Point(2) = {0, 0, R}; PolarSphere(1) = {1, 2};\n"
                              "Field[1] = MathEval; Field[1].F = \"20e3\";\n"
                              "Coastline[1] = LonLatText;\n"
                              "Coastline[1].FileName = \"" SM_SOURCE_DIR "/data/gshhg/northsea_scheldt_f.txt\";\n"
                              "Coastline[1].AccuracyField = 1; Coastline[1].Region = {-4, 9, 48, 58};\n"
                              "open[] = Coastline{1, \"OpenCurves\"};\n"
                              "For i In {0 : #open[] - 1}  Printf(\"%g\", open[i]);  EndFor\n",
                              box);
  CHECK(d.curves > 0);
  MESSAGE(d.curves, " open curves, max deviation ", d.max_m, " m (", d.max_deg, " deg)");
  CHECK(d.max_m < 0.05 * 20e3);   // was 5.8 km
}

TEST_CASE("region box: the Arctic's polar cap (the parallel at 50N)") {
  const double box[4] = {-1000, 1000, 50, 1000};   // only the parallel counts
  const Deviation d = measure("ArchipelagoSize = 60e3; CoastSize = 120e3; EstimateStep = 2; Quiet = 1;\n"
                              "Include \"arctic.geo\";\n"
                              "For i In {0 : #open[] - 1}  Printf(\"%g\", open[i]);  EndFor\n",
                              box);
  CHECK(d.curves > 0);
  MESSAGE(d.curves, " open curves, max deviation ", d.max_m, " m (", d.max_deg, " deg)");
  CHECK(d.max_m < 0.05 * 60e3);   // no corners: control points on the parallel, 1.6 km at gamma >= 60 km
}
