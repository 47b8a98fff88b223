// The time step the summary reports with Mesh.DepthField (mesh/time_step.h) is the one an
// ocean model computes from the fort.14 we write: nodes (lon/lat degrees, depth) and
// triangles read back, edges as great-circle arcs on the Earth of the script.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "interp/interpreter.h"

namespace {

namespace fs = std::filesystem;
using namespace sm;

struct Ts14Node {
  double lon, lat, depth;
};

// Courant-1 dt of a fort.14 on a sphere of radius r.
double ts14_dt(const std::string& path, double r, std::size_t* triangles) {
  std::ifstream in(path);
  std::string title;
  std::getline(in, title);
  std::size_t ne = 0, nn = 0;
  in >> ne >> nn;
  std::map<long, Ts14Node> nodes;
  for (std::size_t i = 0; i < nn; ++i) {
    long id;
    Ts14Node n;
    in >> id >> n.lon >> n.lat >> n.depth;
    nodes[id] = n;
  }
  const double deg = std::numbers::pi / 180;
  auto arc = [&](const Ts14Node& a, const Ts14Node& b) {
    auto xyz = [&](const Ts14Node& n) {
      return std::array<double, 3>{std::cos(n.lat * deg) * std::cos(n.lon * deg),
                                   std::cos(n.lat * deg) * std::sin(n.lon * deg), std::sin(n.lat * deg)};
    };
    const auto p = xyz(a), q = xyz(b);
    const double cx = p[1] * q[2] - p[2] * q[1], cy = p[2] * q[0] - p[0] * q[2], cz = p[0] * q[1] - p[1] * q[0];
    return r * std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  };
  double dt = 1e300;
  for (std::size_t e = 0; e < ne; ++e) {
    long id, three, a, b, c;
    in >> id >> three >> a >> b >> c;
    const Ts14Node &na = nodes.at(a), &nb = nodes.at(b), &nc = nodes.at(c);
    const double h = std::max({na.depth, nb.depth, nc.depth});
    const double edge = std::min({arc(na, nb), arc(nb, nc), arc(nc, na)});
    if (h > 0) dt = std::min(dt, edge / std::sqrt(9.81 * h));
  }
  *triangles = ne;
  return dt;
}

}  // namespace

TEST_CASE("time step: the summary's dt equals the one computed from the written fort.14") {
  const fs::path dir = fs::temp_directory_path() / ("sm_ts14_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "fort.14").string();
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
      // Depths from 30 m to 4 km, varying across the box.
      "Field[2] = MathEval; Field[2].F = \"30 + 4000 * (0.5 + 0.5 * Sin(y / 2e4))\";\n"
      "Mesh.DepthField = 2;\n"
      "Mesh 2;\n"
      "Save \"" + out + "\";\n";
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream printed;
  interp::Interpreter in(sources, diags, printed, {});
  REQUIRE(in.run_buffer("ts14.geo", script) != interp::RunStatus::Errors);
  const double reported = in.options().number("Mesh.StatsTimeStep");
  std::size_t triangles = 0;
  const double from_file = ts14_dt(out, 6371e3, &triangles);
  CHECK(triangles == static_cast<std::size_t>(in.options().number("Mesh.NbTriangles")));
  CHECK(reported > 0);
  // The file holds 15 significant digits.
  CHECK(from_file == doctest::Approx(reported).epsilon(1e-9));
  fs::remove_all(dir);
}
