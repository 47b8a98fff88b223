// Coastline[n].Coordinate = "utm" with UTMZone, UTMEquatorialRadius and UTMPolarRadius:
// the islands of tests/data/coast_scripts/islands_loops2.txt written in UTM zone 30 on
// another ellipsoid than the default (International 1924) import as the same file in
// degrees does, point for point; read on the default ellipsoid (the radii not applied),
// the points move by tens of metres.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include <GeographicLib/TransverseMercator.hpp>
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "interp_test_util.h"

namespace {

constexpr double kUtmA = 6378388.0, kUtmB = 6356911.946;   // International 1924

// The loops2 file in degrees rewritten as UTM zone 30 eastings and northings on kUtmA/kUtmB.
std::string utm_islands() {
  std::ifstream in(SM_SOURCE_DIR "/tests/data/coast_scripts/islands_loops2.txt");
  REQUIRE(in);
  const GeographicLib::TransverseMercator tm(kUtmA, (kUtmA - kUtmB) / kUtmA, 0.9996);
  std::ostringstream out;
  std::size_t n = 0;
  int closed = 0;
  while (in >> n >> closed) {   // a block: its point count and closed flag, then the points
    out << n << " " << closed << "\n";
    for (std::size_t i = 0; i < n; ++i) {
      double lon = 0, lat = 0, x = 0, y = 0;
      REQUIRE(static_cast<bool>(in >> lon >> lat));
      tm.Forward(-3.0, lat, lon, x, y);   // zone 30: central meridian 3W
      out << fmt::format("{:.4f} {:.4f}\n", x + 500000.0, y);
    }
  }
  return out.str();
}

std::string utm_script(const std::string& file, bool radii) {
  return "R = 6371009; Point(1) = {0, 0, 0}; Point(2) = {0, 0, R}; PolarSphere(1) = {1, 2};\n"
         "Field[1] = MathEval; Field[1].F = \"2000\";\n"
         "Coastline[1] = Loops2;\n"
         "Coastline[1].FileName = \"" SM_SOURCE_DIR
         "/tests/data/coast_scripts/islands_loops2.txt\";\n"
         "Coastline[1].AccuracyField = 1;\n"
         "Coastline[2] = Loops2;\n"
         "Coastline[2].FileName = \"" +
         file +
         "\";\n"
         "Coastline[2].Coordinate = \"utm\";\n"
         "Coastline[2].UTMZone = 30;\n" +
         (radii
              ? fmt::format("Coastline[2].UTMEquatorialRadius = {};\nCoastline[2].UTMPolarRadius = {};\n", kUtmA, kUtmB)
              : std::string()) +
         "Coastline[2].AccuracyField = 1;\n"
         "a[] = Coastline{1, \"Points\"};\n"
         "b[] = Coastline{2, \"Points\"};\n"
         "far = 0;\n"
         "If (#a[] == #b[])\n"
         "  For i In {0 : #a[] - 1}\n"
         "    p[] = Point{a[i]}; q[] = Point{b[i]};\n"
         "    far = Max(far, Hypot(Hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]));\n"
         "  EndFor\n"
         "EndIf\n"
         "Printf(\"same count %g, farthest %.3f m\", #a[] == #b[], far);\n";
}

}  // namespace

TEST_CASE("coastline: Loops2 in UTM coordinates on a given ellipsoid") {
  // (Not scratch_dir.h: its namespace sm::testing would make `testing` ambiguous in the
  // unity batch this file shares with the evaluator tests.)
  const std::string file =
      (std::filesystem::temp_directory_path() / fmt::format("sm-coastline-utm-{}.txt", getpid())).string();
  {
    std::ofstream out(file);
    out << utm_islands();
  }
  struct Remove {
    std::string f;
    ~Remove() { std::filesystem::remove(f); }
  } remove_file{file};
  const auto r = sm::interp::testing::run_script(utm_script(file, true));
  INFO(r.rendered);
  REQUIRE(r.ok);
  double far = -1;
  int same = 0;
  REQUIRE(std::sscanf(r.out.c_str(), "same count %d, farthest %lf", &same, &far) == 2);
  CHECK(same == 1);
  CHECK(far < 0.5);   // the file's 0.1 mm rounding, and the coarsening choosing the same points
  // Without the radii the default ellipsoid (WGS84) reads the same numbers elsewhere.
  const auto d = sm::interp::testing::run_script(utm_script(file, false));
  REQUIRE(d.ok);
  REQUIRE(std::sscanf(d.out.c_str(), "same count %d, farthest %lf", &same, &far) == 2);
  CHECK((same == 0 || far > 10));
}
