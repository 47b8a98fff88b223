// ADCIRC fort.14 / SCHISM hgrid.gr3 from a script: a regional model of the Irish
// Sea and the Celtic Sea cut by a lon/lat box, meshed, saved, and read back.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp_test_util.h"
#include "io/ocean_grid.h"
#include "scratch_dir.h"

using sm::interp::testing::run_script;

namespace {


}  // namespace

TEST_CASE("ocean grids: boundaries from the 'open' group, depth from Mesh.DepthField") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_ocean_grid_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string data = SM_DATA_DIR;
  const std::string script =
      "Point(1) = {0, 0, 0}; Point(2) = {0, 0, 6371009};\n"
      "PolarSphere(1) = {1, 2};\n"
      "Field[1] = MathEval; Field[1].F = \"20000\";\n"
      "Coastline[1] = LonLatText;\n"
      "Coastline[1].FileName = \"" + data + "/gshhg/gb_ireland_f.txt\";\n"
      "Coastline[1].AccuracyField = 1;\n"
      "Coastline[1].Region = {-9, -3, 50.5, 55};\n"
      "loops[] = Coastline{1};\n"
      "per[] = Coastline{1, \"LoopsPerSurface\"};\n"
      "Plane Surface(1) = {loops[{0 : per[0] - 1}]};\n"
      "Physical Surface(\"sea\") = {1};\n"
      "Physical Curve(\"open\") = Coastline{1, \"OpenCurves\"};\n"
      "Field[2] = Constant; Field[2].VIn = 25000; Field[2].VOut = 25000;\n"
      "Background Field = 2;\n"
      "Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;\n"
      "Field[3] = Bathymetry;\n"
      "Field[3].FileName = \"" + data + "/bathymetry/etopo5_nw_europe_5min.nc\";\n"
      "Mesh.DepthField = 3;\n"
      "Mesh 2;\n"
      "Printf(\"%g\", Mesh.NbTriangles);\n"
      "Save \"" + (dir / "fort.14").string() + "\";\n"
      "Save \"" + (dir / "hgrid.gr3").string() + "\";\n";
  const auto r = run_script(script);
  INFO(r.rendered);
  REQUIRE(r.ok);
  const int triangles = std::stoi(r.out);
  for (const char* name : {"fort.14", "hgrid.gr3", "hgrid.ll"}) {
    CAPTURE(name);
    sm::io::OceanGrid g;
    std::string error;
    REQUIRE(sm::io::parse_ocean_grid(sm::testing::read_all(dir / name), &g, &error));
    CHECK(static_cast<int>(g.triangles.size() / 3) == triangles);
    // The box's sides are open boundaries: every open node lies on the box, to
    // within how far the closing curves (drawn in the stereographic plane)
    // stray from the parallels: 0.03 degrees here, below the 25 km size.
    REQUIRE(!g.open.empty());
    for (const auto& s : g.open)
      for (std::uint32_t v : s.nodes) {
        const sm::Vec2 ll = g.xy[v];
        const double to_box = std::min({std::abs(ll.x + 9), std::abs(ll.x + 3), std::abs(ll.y - 50.5), std::abs(ll.y - 55)});
        CHECK(to_box < 0.05);
      }
    // Land: the coasts of Ireland, Wales, Cornwall... as mainland strings between open
    // ones, and islands (Anglesey, the Isle of Man) as closed island strings.
    int mainland = 0, islands = 0;
    for (const auto& s : g.land) (s.type == 20 || s.type == 0 ? mainland : islands)++;
    CHECK(mainland >= 2);
    CHECK(islands >= 2);
    // Depth from ETOPO5, positive down: the Celtic Sea is 50-200 m deep.
    double deepest = 0;
    for (double h : g.depth) deepest = std::max(deepest, h);
    CHECK(deepest > 50);
    CHECK(deepest < 6000);
  }
  fs::remove_all(dir);
}
