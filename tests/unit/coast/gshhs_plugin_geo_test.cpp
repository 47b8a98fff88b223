// Plugin(GSHHS) compatibility writer: structure of the .geo text, options, and Gmsh 4.8.4
// reading the file for the world (run when gmsh is installed, else skipped with a message).
#include "coast/gshhs_plugin_geo.h"
#include "coast/read_lonlat_text.h"

#include <unistd.h>
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "coast/constant_accuracy.h"

using namespace sm;
using namespace sm::coast;

namespace {
namespace fs = std::filesystem;


std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// Runs a command, returns its exit status and merged output.
int run(const std::string& cmd, std::string& out) {
  out.clear();
  std::FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return -1;
  std::array<char, 4096> buf;
  while (std::fgets(buf.data(), buf.size(), p)) out += buf.data();
  return pclose(p);
}

bool have_gmsh() {
  std::string out;
  return run("gmsh --version", out) == 0 && out.find("4.") != std::string::npos;
}

// Error lines Gmsh prints, except its known refusal to export a parametric (PolarSphere)
// surface to .geo_unrolled under -0, which is not a reading error.
std::vector<std::string> gmsh_errors(const std::string& out) {
  std::vector<std::string> errs;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);)
    if (line.find("Error") != std::string::npos && line.find("in export") == std::string::npos) errs.push_back(line);
  return errs;
}

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("sm_coast_plugin_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST_CASE("plugin: world crude GSHHS at 100 km, the .geo text") {
  GshhsPluginOptions o;
  o.in_file_name = std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b";
  o.out_file_name = (temp_dir() / "earth.geo").string();
  o.field = sm::testing::constant_accuracy(100e3);
  auto r = run_gshhs_plugin(o);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  const std::string& g = r->geo;
  CHECK(g.rfind("IP = newp;  IL = newl;  ILL = newll;  IS = news;  IFI = newf;\n", 0) == 0);
  CHECK(g.find("Point ( IP + 1 ) = {0, 0,6371009};") != std::string::npos);
  CHECK(count(g, "PolarSphere ( IS + 0 ) = {IP , IP+1};") == 1);
  std::size_t pts = 0;
  for (const auto& c : r->model.curves) pts += c.uv.size();
  CHECK(count(g, "Point ( IP + ") == pts + 2);
  CHECK(count(g, "BSpline ( IL + ") == r->model.curves.size());
  CHECK(count(g, "Line Loop ( ILL + ") == r->model.loops.size());
  CHECK(count(g, "Plane Surface ( IS + 0 ) = { ILL + 0, ILL + 1,") == 1);   // the Gmsh 2.6 bug, fixed
  CHECK(count(g, "= Distance;") == 1);
  // The written file is the returned text, and points are the model's (u,v) at %.16g.
  std::ifstream f(o.out_file_name);
  std::stringstream ss;
  ss << f.rdbuf();
  CHECK(ss.str() == g);
  const Vec2 uv0 = r->model.curves[0].uv[0];
  char line[200];
  std::snprintf(line, sizeof line, "Point ( IP + 2 ) = {%.16g, %.16g, 0 };", uv0.x, uv0.y);
  CHECK(g.find(line) != std::string::npos);
}

TEST_CASE("plugin: Gmsh 4.8.4 reads the generated world file") {
  if (!have_gmsh()) {
    MESSAGE("gmsh not installed: skipping the Gmsh 4.8.4 reading check");
    return;
  }
  GshhsPluginOptions o;
  o.in_file_name = std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b";
  o.out_file_name = (temp_dir() / "world_c.geo").string();
  o.field = sm::testing::constant_accuracy(100e3);
  REQUIRE(run_gshhs_plugin(o).ok());
  std::string out;
  CHECK(run("gmsh '" + o.out_file_name + "' -parse_and_exit", out) == 0);
  CHECK_MESSAGE(gmsh_errors(out).empty(), out);
  // gmsh -0 exits with 1 because it refuses to export the PolarSphere surface to
  // .geo_unrolled ("Skipping surface 1 in export"); reading must raise no other error.
  run("cd '" + temp_dir().string() + "' && gmsh -0 world_c.geo", out);
  CHECK_MESSAGE(gmsh_errors(out).empty(), out);
  CHECK(out.find("Done reading") != std::string::npos);
}

TEST_CASE("plugin: loops2 input, WritePolarSphere = 0 and -2, bad options") {
  GshhsPluginOptions o;
  o.in_file_name = std::string(SM_TEST_DATA) + "/coast/gb_islands_loops2.txt";
  o.out_file_name = (temp_dir() / "islands.geo").string();
  o.format = "loops2";
  o.coordinate = "lonlat_degrees";
  o.write_polar_sphere = 0;
  auto r = run_gshhs_plugin(o);   // no field: every point kept
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  CHECK(r->model.surfaces.empty());              // no ring round the South Pole
  CHECK(r->model.unassigned.size() == 4);
  CHECK(r->geo.find("PolarSphere") == std::string::npos);
  CHECK(r->geo.find("Plane Surface") == std::string::npos);
  CHECK(count(r->geo, "Line Loop") == 4);
  o.write_polar_sphere = -2;
  auto p = run_gshhs_plugin(o);
  REQUIRE(p.ok());
  const Vec2 uv = p->model.curves[0].uv[0];
  char line[200];
  std::snprintf(line, sizeof line, "Point ( IP + 0 ) = {%.16g, %.16g, 0 };", -2 * o.radius * uv.x,
                -2 * o.radius * uv.y);
  CHECK(p->geo.find(line) != std::string::npos);
  if (have_gmsh()) {
    std::string out;
    CHECK(run("gmsh '" + o.out_file_name + "' -parse_and_exit", out) == 0);
    CHECK_MESSAGE(gmsh_errors(out).empty(), out);
  }
  GshhsPluginOptions bad = o;
  bad.format = "shapefile";
  CHECK_FALSE(run_gshhs_plugin(bad).ok());
  bad = o;
  bad.coordinate = "polar";
  CHECK_FALSE(run_gshhs_plugin(bad).ok());
  bad = o;
  bad.write_polar_sphere = 3;
  CHECK_FALSE(run_gshhs_plugin(bad).ok());
  bad = o;
  bad.out_file_name = "/nonexistent_dir/x.geo";
  CHECK_FALSE(run_gshhs_plugin(bad).ok());
  bad = o;
  bad.in_file_name = "/nonexistent.txt";
  CHECK_FALSE(run_gshhs_plugin(bad).ok());
}

TEST_CASE("plugin writer: a regional model (cut coasts closed along the box) meshes in Gmsh 4.8.4") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(c.ok());
  ImportOptions io;
  io.gamma = sm::testing::constant_accuracy(15e3);
  auto m = build_coast_model(std::move(*c), io);
  REQUIRE(m.ok());
  const std::string geo = write_gshhs_plugin_geo(*m, GshhsPluginOptions{});
  // The outer loop: 2 French coast pieces and 2 box pieces, chained point to point.
  CHECK(count(geo, "Line Loop ( ILL + 0 ) = { IL + 0, IL + 1, IL + 2, IL + 3 };") == 1);
  CHECK(count(geo, "Physical Curve ( \"open\" )") == 1);
  if (!have_gmsh()) {
    MESSAGE("gmsh not installed: skipping the Gmsh 4.8.4 meshing check");
    return;
  }
  const fs::path f = temp_dir() / "gb_region.geo";
  {
    std::ofstream out(f);
    out << geo << "Mesh.CharacteristicLengthMax = 20e3;\nMesh.CharacteristicLengthFromPoints = 0;\n";
  }
  std::string out;
  CHECK(run("gmsh -2 '" + f.string() + "' -o '" + (temp_dir() / "gb_region.msh").string() + "'", out) == 0);
  CHECK_MESSAGE(gmsh_errors(out).empty(), out);
  CHECK(out.find(" nodes ") != std::string::npos);
}

TEST_CASE("plugin: a negative field value cuts loops (Gmsh 2.6's way to crop to a region)") {
  GshhsPluginOptions o;
  o.in_file_name = std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b";
  o.out_file_name = (temp_dir() / "crop.geo").string();
  // 20 km inside -12/3/48/62 (around Great Britain), -1 outside.
  o.field = [](std::span<const Vec3> pts, std::span<double> g) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const geo::LonLat ll = geo::lonlat_from_sphere(pts[i]);
      g[i] = (ll.lon >= -12 && ll.lon <= 3 && ll.lat >= 48 && ll.lat <= 62) ? 20e3 : -1;
    }
  };
  auto r = run_gshhs_plugin(o);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  CHECK_FALSE(r->cut.empty());                       // the continent's coast, cut at the box
  for (const auto& c : r->cut)
    for (auto p : c.ll) {
      CHECK(p.lat >= 48);
      CHECK(p.lat <= 62);
    }
  bool gb = false;
  for (const auto& c : r->model.curves) gb |= c.periodic && c.id == 15;   // Great Britain stays a whole loop
  CHECK(gb);
  CHECK(r->model.surfaces.empty());                  // Antarctica was cut away: no outer loop
  CHECK(count(r->geo, "BSpline ( IL + ") + count(r->geo, "Line ( IL + ") == r->model.curves.size() + r->cut.size());
  CHECK(count(r->geo, "Line Loop") == r->model.loops.size());
  if (have_gmsh()) {
    std::string out;
    CHECK(run("gmsh '" + o.out_file_name + "' -parse_and_exit", out) == 0);
    CHECK_MESSAGE(gmsh_errors(out).empty(), out);
  }
}
