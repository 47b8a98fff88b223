// The MinDepth account of a Bathymetry depth field (Mesh.DepthField): the summary's count
// and place of the largest raise against the depths the fort.14 holds, on a grid whose
// shallow part is known: depth 10 (lon + 2) m, the same at every latitude.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "interp/interpreter.h"
#include "interp/kernel_state.h"

namespace {

struct ClampNode {
  double lon, lat, depth;
};

std::vector<ClampNode> clamp_fort14_nodes(const std::string& path) {
  std::ifstream in(path);
  std::string title;
  std::getline(in, title);
  std::size_t ne = 0, nn = 0;
  in >> ne >> nn;
  std::vector<ClampNode> nodes(nn);
  for (ClampNode& n : nodes) {
    long id;
    in >> id >> n.lon >> n.lat >> n.depth;
  }
  return nodes;
}

struct ClampRun {
  sm::field::DepthClampReport report;
  double stats_clamped = 0;
  std::vector<ClampNode> nodes;
};

ClampRun clamp_run(const std::filesystem::path& dir, int sampling) {
  const std::string grid = (dir / "ramp.asc").string(), out = (dir / "fort.14").string();
  {
    // Columns at lon -1.75 .. 2.25, rows at lat -1.5 .. 1.5: depth 10 (lon + 2).
    std::ofstream g(grid);
    g << "ncols 5\nnrows 4\nxllcenter -1.75\nyllcenter -1.5\ncellsize 1\n";
    for (int r = 0; r < 4; ++r) g << "2.5 12.5 22.5 32.5 42.5\n";
  }
  const std::string script =
      "R = 6371e3;\n"
      "Point(1) = {0, 0, 0}; Point(2) = {0, 0, R}; PolarSphere(1) = {1, 2};\n"
      "Field[1] = MathEval; Field[1].F = \"20e3\";\n"
      "Coastline[1] = Loops2;\n"
      "Coastline[1].FileName = \"" SM_TEST_DATA "/field/strait_loops2.txt\";\n"
      "Coastline[1].AccuracyField = 1; Coastline[1].CurveType = \"Line\";\n"
      "Coastline[1].Region = {-0.5, 1.6, -0.5, 1.0};\n"
      "loops[] = Coastline{1};\n"
      "Plane Surface(1) = loops[];\n"
      "Background Field = 1;\n"
      "Field[2] = Bathymetry; Field[2].FileName = \"" + grid + "\";\n"
      "Field[2].Positive = \"down\"; Field[2].MinDepth = 20;\n"
      "Mesh.DepthField = 2;\n"
      "Mesh.DepthSampling = " + std::to_string(sampling) + ";\n"
      "Mesh 2;\n"
      "Save \"" + out + "\";\n";
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  std::ostringstream printed;
  sm::interp::Interpreter in(sources, diags, printed, {});
  REQUIRE(in.run_buffer("clamp.geo", script) != sm::interp::RunStatus::Errors);
  ClampRun run;
  REQUIRE(in.kernel().has_mesh_stats);
  REQUIRE(in.kernel().mesh_stats.has_depth_clamp);
  run.report = in.kernel().mesh_stats.depth_clamp;
  run.stats_clamped = in.options().number("Mesh.StatsDepthClamped");
  run.nodes = clamp_fort14_nodes(out);
  return run;
}

}  // namespace

TEST_CASE("depth clamp: count and place of the MinDepth raise, as the fort.14 has them") {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("sm_depth_clamp_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    // Bilinear: the grid is clamped before it is interpolated, so MinDepth 20 raises the
    // values at lon -1.75 and -0.75 and with them every node west of lon 0.25; the most
    // (7.5 - 7.5 t, t = lon + 0.75) on the west edge, lon -0.5: 15 m -> 20.625 m.
    const ClampRun run = clamp_run(dir, 0);
    std::uint64_t west = 0;
    for (const ClampNode& n : run.nodes) {
      if (n.lon < 0.25) ++west;
      const double raw = 10 * (n.lon + 2);
      if (n.lon >= 0.25) CHECK(n.depth == doctest::Approx(raw));
      else CHECK(n.depth > raw);
    }
    CHECK(west > 0);
    CHECK(run.report.points == run.nodes.size());
    CHECK(run.report.clamped == west);
    CHECK(run.stats_clamped == static_cast<double>(west));
    CHECK(run.report.min_depth == 20);
    REQUIRE(run.report.has_worst);
    CHECK(run.report.lon == doctest::Approx(-0.5).epsilon(1e-9));
    CHECK(run.report.lat >= -0.5 - 1e-9);
    CHECK(run.report.lat <= 1.0 + 1e-9);
    CHECK(run.report.grid_depth == doctest::Approx(15));
    CHECK(run.report.value == doctest::Approx(20.625));
  }
  {
    // Cell means: a raised node gets MinDepth itself, and only those do.
    const ClampRun run = clamp_run(dir, 1);
    std::uint64_t at_min = 0;
    for (const ClampNode& n : run.nodes) {
      CHECK(n.depth >= 20);
      if (n.depth == 20) ++at_min;
    }
    CHECK(at_min > 0);
    CHECK(run.report.clamped == at_min);
    CHECK(run.report.value == 20);
    CHECK(run.report.grid_depth < 20);
  }
  std::filesystem::remove_all(dir);
}
