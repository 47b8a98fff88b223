// The open boundaries of a Region polygon follow its great-circle edges: the Irish Sea
// polygon of tests/scripts/coastline/region_polygon.geo, its two open curves (St George's
// Channel, the North Channel) sampled densely on the model curves and each sample's
// distance to the polygon's edges measured with the test's own spherical geometry.
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

constexpr double kDeg = 3.14159265358979323846 / 180;

Vec3 unit(double lon, double lat) {
  return {std::cos(lat * kDeg) * std::cos(lon * kDeg), std::cos(lat * kDeg) * std::sin(lon * kDeg),
          std::sin(lat * kDeg)};
}

const double kPolygon[] = {-5.27, 51.89, -2.2, 52.2, -2.2, 55.3, -4.5, 55.1, -5.0, 54.90,
                           -6.10, 55.17, -7.5, 54.5, -7.5, 52.5, -6.45, 52.22};

}  // namespace

TEST_CASE("region polygon: the open curves lie on the polygon's great-circle edges") {
  std::string region;
  for (double v : kPolygon) region += (region.empty() ? "" : ", ") + std::to_string(v);
  const std::string script =
      "R = 6371009; Point(1) = {0, 0, 0}; Point(2) = {0, 0, R}; PolarSphere(1) = {1, 2};\n"
      "Field[1] = MathEval; Field[1].F = \"2000\";\n"
      "Coastline[1] = LonLatText; Coastline[1].FileName = \"" SM_SOURCE_DIR "/data/gshhg/gb_ireland_f.txt\";\n"
      "Coastline[1].AccuracyField = 1; Coastline[1].Region = {" + region + "};\n"
      "Coastline[1].SeaAt = {-5.4, 53.35};\n"
      "open[] = Coastline{1, \"OpenCurves\"};\n"
      "For i In {0 : #open[] - 1}  Printf(\"%g\", open[i]);  EndFor\n";
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream out;
  interp::RunSettings settings;
  settings.stdlib_dir = SM_SOURCE_DIR "/stdlib";
  interp::Interpreter in(sources, diags, out, settings);
  in.run_buffer(SM_SOURCE_DIR "/examples/polygon_test.geo", script);
  INFO(diags.render_all());
  REQUIRE(diags.error_count() == 0);
  const geo::Model& model = in.kernel().model;
  const auto& [gtag, g] = *model.geometries().begin();
  const geo::PolarSphere sphere(g.centre(), g.radius());
  std::vector<int> tags;
  std::istringstream lines(out.str());
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line.find_first_not_of("0123456789") == std::string::npos) tags.push_back(std::stoi(line));
  REQUIRE(tags.size() == 2);
  const std::size_t n = std::size(kPolygon) / 2;
  for (const int tag : tags) {
    const geo::ModelCurve* c = model.curve(tag);
    REQUIRE(c);
    double worst = 0, length = 0;
    Vec3 prev{};
    for (int k = 0; k <= 2000; ++k) {
      const geo::LonLat ll = sphere.to_lonlat(c->shape->point(k / 2000.0));
      const Vec3 u = unit(ll.lon, ll.lat);
      if (k > 0) length += norm(u - prev) * g.radius();
      prev = u;
      // Metres to the nearest edge's great circle, for the edges whose arc holds the point.
      double best = 1e30;
      for (std::size_t e = 0; e < n; ++e) {
        const Vec3 a = unit(kPolygon[2 * e], kPolygon[2 * e + 1]);
        const Vec3 b = unit(kPolygon[2 * ((e + 1) % n)], kPolygon[2 * ((e + 1) % n) + 1]);
        Vec3 nrm = cross(a, b);
        nrm = nrm / norm(nrm);
        if (dot(cross(a, u), nrm) < -1e-6 || dot(cross(u, b), nrm) < -1e-6) continue;
        best = std::min(best, std::asin(std::min(1.0, std::abs(dot(u, nrm)))) * g.radius());
      }
      worst = std::max(worst, best);
    }
    MESSAGE("open curve ", tag, ": ", length / 1000, " km long, at most ", worst, " m off its edge");
    CHECK(length > 20e3);        // a channel, not a grazing crossing
    CHECK(worst < 0.05 * 2000);  // within 5% of gamma of the great circle
  }
}
