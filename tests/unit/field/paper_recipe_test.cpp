// The paper's three criteria (section 3.1) on real data: shore distance to
// the GSHHG Great Barrier Reef coastline, the wavelength and Hessian criteria
// of ETOPO5, each through Threshold, combined by Min, then graded.
#include <cmath>
#include <fstream>
#include <sstream>

#include <doctest/doctest.h>

#include "field/lonlat_grid.h"
#include "field/min_max.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::repo_data;

TEST_CASE("paper recipe: f1, f2, f3 on the Great Barrier Reef, Min, argmin, Gradation") {
  std::ifstream in(repo_data("gshhg/gbr_lizard_f.txt"));
  REQUIRE(in);
  std::vector<Vec3> coast;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == '>') continue;
    std::istringstream ls(line);
    double lon, lat;
    ls >> lon >> lat;
    coast.push_back(point_of(lon, lat, 1));
  }
  REQUIRE(coast.size() == 72749);
  BuildContext ctx;
  ctx.point_position = [&](int tag) -> std::optional<Vec3> {
    if (tag < 1 || tag > static_cast<int>(coast.size())) return std::nullopt;
    return coast[static_cast<std::size_t>(tag - 1)];
  };
  const double r = 6371e3;
  const std::string nc = repo_data("bathymetry/etopo5_gbr_5min.nc");
  FieldSet fs;
  fs.define(1, "Distance");
  std::vector<double> tags(coast.size());
  for (std::size_t i = 0; i < tags.size(); ++i) tags[i] = static_cast<double>(i + 1);
  fs.set(1, "PointsList", tags);
  fs.define(2, "Threshold");
  fs.set(2, "InField", 1.0);
  fs.set(2, "SizeMin", 1e3 / r);
  fs.set(2, "SizeMax", 20e3 / r);
  fs.set(2, "DistMin", 0.0);
  fs.set(2, "DistMax", 50e3 / r);
  fs.define(3, "Bathymetry");
  fs.set(3, "FileName", nc);
  fs.set(3, "Output", std::string("wavelength"));
  fs.set(3, "WaveLengthMin", 20e3 / r);
  fs.set(3, "PointsPerWaveLength", 1.0);
  fs.set(3, "DepthRef", 1000.0);
  fs.define(4, "Threshold");
  fs.set(4, "InField", 3.0);
  fs.set(4, "SizeMin", 2e3 / r);
  fs.set(4, "SizeMax", 20e3 / r);
  fs.set(4, "DistMin", 2e3 / r);
  fs.set(4, "DistMax", 20e3 / r);
  fs.define(5, "Bathymetry");
  fs.set(5, "FileName", nc);
  fs.set(5, "Output", std::string("hessian"));
  fs.set(5, "DepthRef", 1000.0);
  fs.define(6, "MathEval");
  fs.set(6, "F", "F5 / " + std::to_string(r));
  fs.define(7, "Threshold");
  fs.set(7, "InField", 6.0);
  fs.set(7, "SizeMin", 3e3 / r);
  fs.set(7, "SizeMax", 20e3 / r);
  fs.set(7, "DistMin", 10e3 / r);
  fs.set(7, "DistMax", 100e3 / r);
  fs.define(8, "Min");
  fs.set(8, "FieldsList", std::vector<double>{2, 4, 7});
  fs.define(9, "Gradation");
  fs.set(9, "InField", 8.0);
  fs.set(9, "Rate", 0.1);
  fs.set(9, "Resolution", 0.1);
  fs.set(9, "LonMin", 140.0);
  fs.set(9, "LonMax", 156.0);
  fs.set(9, "LatMin", -26.0);
  fs.set(9, "LatMax", -9.0);
  BuiltFields b = fs.build(9, ctx);

  std::vector<Vec3> pts;
  for (double lon = 140.5; lon < 156; lon += 0.25)
    for (double lat = -25.5; lat < -9; lat += 0.25) pts.push_back(point_of(lon, lat, 1));
  std::vector<double> h(pts.size()), g(pts.size()), d(pts.size());
  std::vector<int> which(pts.size());
  REQUIRE(eval_argmin(*b.get(8), nullptr, pts, h, which));
  b.get(9)->eval(pts, g);
  b.get(1)->eval(pts, d);
  int wins[3] = {0, 0, 0};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    CHECK(h[i] >= 1e3 / r * (1 - 1e-9));
    CHECK(h[i] <= 20e3 / r * (1 + 1e-9));
    // Graded sizes never exceed the input (up to interpolation between nodes
    // of the background grid) and stay positive.
    CHECK(g[i] > 0);
    CHECK(g[i] <= 20e3 / r * (1 + 1e-9));
    wins[which[i] == 2 ? 0 : which[i] == 4 ? 1 : 2]++;
    // On the coast the shore criterion is the finest possible size.
    if (d[i] < 1e-9) CHECK(which[i] == 2);
  }
  // Every criterion controls the size somewhere in the region.
  CHECK(wins[0] > 0);
  CHECK(wins[1] > 0);
  CHECK(wins[2] > 0);
  // Gradation removes the jumps: between neighbouring sample points 0.25
  // degrees apart, the graded size changes by at most Rate times their
  // distance (plus the interpolation slack of the 0.1-degree grid).
  const std::size_t nlat = 66;
  double worst = 0, worst_in = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    if ((i + 1) % nlat == 0) continue;
    const double dist = norm(pts[i] - pts[i + 1]);
    worst = std::max(worst, std::fabs(g[i] - g[i + 1]) / dist);
    worst_in = std::max(worst_in, std::fabs(h[i] - h[i + 1]) / dist);
  }
  CHECK(worst <= 0.1 * 1.05);
  CHECK(worst_in > 0.1);
}
