// ADCIRC fort.14 / SCHISM hgrid.gr3 from a script: a regional model of the Irish
// Sea and the Celtic Sea cut by a lon/lat box, meshed, saved, and read back.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <utility>
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
        const double to_box =
            std::min({std::abs(ll.x + 9), std::abs(ll.x + 3), std::abs(ll.y - 50.5), std::abs(ll.y - 55)});
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

namespace {

// Sides of one triangle only, as (smaller, larger) 0-based nodes.
std::set<std::pair<std::uint32_t, std::uint32_t>> boundary_of(const sm::io::OceanGrid& g) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (std::size_t i = 0; i + 3 <= g.triangles.size(); i += 3)
    for (int j = 0; j < 3; ++j) {
      std::uint32_t a = g.triangles[i + j], b = g.triangles[i + (j + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.insert(e);
  return out;
}

}  // namespace

TEST_CASE("ocean grids: every boundary edge listed once, closed loops closed, left-out islands not listed") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_ocean_loops_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A square basin without open boundary (its coast one closed mainland loop), a square
  // island that is meshed, and a B-spline islet far below the size that mesh2d leaves out.
  const std::string script =
      "lc = 0.1;\n"
      "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Point(5) = {0.4, 0.4, 0, lc}; Point(6) = {0.6, 0.4, 0, lc}; Point(7) = {0.6, 0.6, 0, lc};\n"
      "Point(8) = {0.4, 0.6, 0, lc};\n"
      "Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};\n"
      "Point(9) = {0.2, 0.2, 0, lc}; Point(10) = {0.205, 0.2, 0, lc}; Point(11) = {0.2, 0.205, 0, lc};\n"
      "BSpline(9) = {9, 10, 11, 9};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8}; Curve Loop(3) = {9};\n"
      "Plane Surface(1) = {1, 2, 3};\n"
      "Physical Surface(\"sea\") = {1};\n"
      "Physical Curve(\"coast\") = {1:9};\n"
      "Mesh 2;\n"
      "Printf(\"%g %g\", Mesh.NbNodes, Mesh.NbTriangles);\n"
      "Save \"" + (dir / "fort.14").string() + "\";\n"
      "Save \"" + (dir / "hgrid.gr3").string() + "\";\n";
  const auto r = run_script(script);
  INFO(r.rendered);
  REQUIRE(r.ok);
  CHECK(r.rendered.find("1 island smaller than the mesh size is left out") != std::string::npos);
  std::istringstream counts(r.out);
  std::size_t nodes = 0, triangles = 0;
  counts >> nodes >> triangles;
  for (const char* name : {"fort.14", "hgrid.gr3"}) {
    CAPTURE(name);
    const bool adcirc = std::string(name) == "fort.14";
    sm::io::OceanGrid g;
    std::string error;
    REQUIRE(sm::io::parse_ocean_grid(sm::testing::read_all(dir / name), &g, &error));
    // The mesh and only the mesh: the summary's counts, every node a triangle's.
    CHECK(g.xy.size() == nodes);
    CHECK(g.triangles.size() / 3 == triangles);
    CHECK(std::set<std::uint32_t>(g.triangles.begin(), g.triangles.end()).size() == nodes);
    CHECK(g.open.empty());
    // The basin's coast (mainland: IBTYPE 20, SCHISM 0) and the meshed island (21 / 1).
    REQUIRE(g.land.size() == 2);
    const auto& mainland = g.land[0].type == (adcirc ? 20 : 0) ? g.land[0] : g.land[1];
    const auto& island = &mainland == &g.land[0] ? g.land[1] : g.land[0];
    CHECK(island.type == (adcirc ? 21 : 1));
    // Closed: the mainland loop repeats its first node in both; the island in fort.14
    // (ADCIRC), not in hgrid.gr3 (SCHISM closes its islands itself).
    CHECK(mainland.nodes.front() == mainland.nodes.back());
    CHECK((island.nodes.front() == island.nodes.back()) == adcirc);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> listed;
    for (const auto* s : {&mainland, &island}) {
      for (std::size_t k = 0; k + 1 < s->nodes.size(); ++k)
        ++listed[{std::min(s->nodes[k], s->nodes[k + 1]), std::max(s->nodes[k], s->nodes[k + 1])}];
      if (!adcirc && s == &island)
        ++listed[{std::min(s->nodes.back(), s->nodes.front()), std::max(s->nodes.back(), s->nodes.front())}];
    }
    const auto boundary = boundary_of(g);
    CHECK(listed.size() == boundary.size());
    for (const auto& [e, n] : listed) {
      CHECK(n == 1);
      CHECK(boundary.count(e) == 1);
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("ocean grids: a curve between two meshed faces is in no boundary list") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_ocean_two_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Two squares side by side sharing Line(2); the right one's far side open.
  const std::string script =
      "lc = 0.2;\n"
      "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {2, 0, 0, lc};\n"
      "Point(4) = {2, 1, 0, lc}; Point(5) = {1, 1, 0, lc}; Point(6) = {0, 1, 0, lc};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};\n"
      "Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, -2};\n"
      "Plane Surface(1) = {1}; Plane Surface(2) = {2};\n"
      "Physical Curve(\"open\") = {6};\n"
      "Mesh 2;\n"
      "Save \"" + (dir / "fort.14").string() + "\";\n"
      "Save \"" + (dir / "hgrid.gr3").string() + "\";\n";
  const auto r = run_script(script);
  INFO(r.rendered);
  REQUIRE(r.ok);
  for (const char* name : {"fort.14", "hgrid.gr3"}) {
    CAPTURE(name);
    sm::io::OceanGrid g;
    std::string error;
    REQUIRE(sm::io::parse_ocean_grid(sm::testing::read_all(dir / name), &g, &error));
    REQUIRE(g.open.size() == 1);
    CHECK(g.land.size() == 3);   // the left square's three sides, the right one's bottom and top
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> listed;
    for (const auto* strings : {&g.open, &g.land})
      for (const auto& s : *strings)
        for (std::size_t k = 0; k + 1 < s.nodes.size(); ++k)
          ++listed[{std::min(s.nodes[k], s.nodes[k + 1]), std::max(s.nodes[k], s.nodes[k + 1])}];
    const auto boundary = boundary_of(g);
    CHECK(listed.size() == boundary.size());
    for (const auto& [e, n] : listed) {
      CHECK(n == 1);
      CHECK(boundary.count(e) == 1);
    }
  }
  fs::remove_all(dir);
}
