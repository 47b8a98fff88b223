// interp/kernel/mesh_commands: meshing asked by -1 / -2 (mesh_from_command_line) reports
// each mesh-stage failure at the statement that created the entity (file:line:col with the
// caret), the element budget (Mesh.MaxElements) included, and writes nothing then.
#include "interp/kernel/mesh_commands.h"

#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "interp/interpreter.h"

namespace {

namespace fs = std::filesystem;
using namespace sm;

struct CliMesh {
  bool ok = false;
  std::string first;      // "line:col kind" of the first error
  std::string rendered;   // as the CLI prints the diagnostics
  bool wrote = false;     // the output file exists
};

// Runs `text` as "cli.geo", then meshes it as `-dim` would, to a file in a fresh folder.
CliMesh mesh_cli(const std::string& text, int dim) {
  const fs::path dir = fs::temp_directory_path() / ("sm_mesh_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "out.msh").string();
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream printed;
  interp::Interpreter in(sources, diags, printed, {});
  CliMesh r;
  REQUIRE(in.run_buffer("cli.geo", text) != interp::RunStatus::Errors);
  r.ok = interp::mesh_from_command_line(in, dim, out, "", "cli.geo");
  for (const auto& d : diags.all()) {
    if (d.severity != lang::Severity::Error) continue;
    const lang::LineCol lc = d.range.valid() ? sources.line_col(d.range.begin_loc()) : lang::LineCol{};
    r.first = std::to_string(lc.line) + ":" + std::to_string(lc.col) + " " + std::string(lang::diag_info(d.kind).kebab);
    break;
  }
  r.rendered = diags.render_all();
  r.wrote = fs::exists(out);
  fs::remove_all(dir);
  return r;
}

const std::string kSquareWithLc =
    "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4};\n"
    "  Plane Surface(1) = {1};\n";

}  // namespace

TEST_CASE("mesh commands: -2 over the element budget is located at the surface's statement") {
  const CliMesh r = mesh_cli("lc = 1e-5;\n" + kSquareWithLc, 2);
  CHECK_FALSE(r.ok);
  CHECK(r.first == "5:3 limit-exceeded");
  CHECK(r.rendered.find("cli.geo:5:3: error: surface 1 would get about 2.3e+10 triangles, over Mesh.MaxElements = "
                        "2e+08: check the mesh sizes, or raise Mesh.MaxElements [limit-exceeded]") !=
        std::string::npos);
  CHECK(r.rendered.find("^") != std::string::npos);
  CHECK_FALSE(r.wrote);
}

TEST_CASE("mesh commands: a size field of 1e-7 is refused on the coarse boundary, before placing nodes") {
  const CliMesh r = mesh_cli("lc = 1;\n" + kSquareWithLc +
                                 "Field[1] = MathEval; Field[1].F = \"1e-7\"; Background Field = 1;\n",
                             2);
  CHECK_FALSE(r.ok);
  CHECK(r.first == "5:3 limit-exceeded");
  CHECK(r.rendered.find("surface 1 would get about 2.3e+14 triangles") != std::string::npos);
  CHECK_FALSE(r.wrote);
}

TEST_CASE("mesh commands: -1 with a size factor of 1e-20 is located at the curve's statement") {
  const CliMesh r = mesh_cli("lc = 0.1;\nMesh.MeshSizeFactor = 1e-20;\n" + kSquareWithLc, 1);
  CHECK_FALSE(r.ok);
  CHECK(r.first == "4:1 limit-exceeded");
  CHECK(r.rendered.find("curve 1 would get about 1.0e+21 nodes") != std::string::npos);
  CHECK_FALSE(r.wrote);
}

TEST_CASE("mesh commands: a 1D failure from -2 points at the statement of a curve it names") {
  // Two squares touching at a corner through distinct points: distinct nodes at one place.
  CliMesh r = mesh_cli(
      "lc = 0.5;\n" + kSquareWithLc +
          "Point(5) = {1, 1, 0, lc}; Point(6) = {2, 1, 0, lc}; Point(7) = {2, 2, 0, lc}; Point(8) = {1, 2, 0, lc};\n"
          "Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};\n"
          "Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};\n",
      2);
  CHECK_FALSE(r.ok);
  CHECK(r.rendered.find("have distinct nodes at the same place") != std::string::npos);
  CHECK(r.first.find(" curves-intersect") != std::string::npos);
  CHECK(r.first.rfind("0:0", 0) != 0);
  CHECK(r.rendered.find("^") != std::string::npos);
  CHECK_FALSE(r.wrote);
}

TEST_CASE("mesh commands: a 2D failure notes the surface and the curve it names (one mesh error shape)") {
  // An embedded point on a boundary edge: the face's edge recovery finds it touching curve 1.
  const CliMesh r =
      mesh_cli("lc = 10;\n" + kSquareWithLc + "Point(5) = {0.5, 0, 0, lc};\nPoint{5} In Surface{1};\n", 2);
  CHECK_FALSE(r.ok);
  CHECK(r.first == "5:3 mesh-error");   // -2: at the statement that created the surface
  CHECK(r.rendered.find("surface 1: a boundary node lies on an edge of curve 1") != std::string::npos);
  CHECK(r.rendered.find("cli.geo:3:1: note: curve 1 was created here") != std::string::npos);
  CHECK_FALSE(r.wrote);
}

TEST_CASE("mesh commands: Mesh.DepthField naming no field is refused before meshing, at its assignment") {
  const CliMesh r = mesh_cli("lc = 0.5;\n" + kSquareWithLc + "Mesh.DepthField = 7;\n", 2);
  CHECK_FALSE(r.ok);
  CHECK(r.first == "6:1 invalid-option-value");
  CHECK(r.rendered.find("Mesh.DepthField = 7 names no field") != std::string::npos);
  CHECK_FALSE(r.wrote);
}

TEST_CASE("mesh commands: an algorithm the kernel lacks is located at the assignment that chose it") {
  const CliMesh r = mesh_cli("lc = 0.5;\n" + kSquareWithLc + "Mesh.Algorithm = 7;\n", 2);
  CHECK_FALSE(r.ok);
  CHECK(r.first == "6:1 mesh-error");
  CHECK(r.rendered.find("Mesh.Algorithm 7 is not available") != std::string::npos);
  CHECK_FALSE(r.wrote);
}
