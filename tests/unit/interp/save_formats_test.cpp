// `Save "f.ext";` and the command line's -format write each format of io/output_format.h
// alike: Save picks the first row with the file's extension, -format picks it by name.
#include <doctest/doctest.h>

#include <set>
#include <sstream>
#include <string>

#include "interp/interpreter.h"
#include "interp/kernel/mesh_commands.h"
#include "io/output_format.h"
#include "scratch_dir.h"

namespace {

using namespace sm;

const std::string kSaveSquare =
    "Point(1) = {0, 0, 0, 0.4}; Point(2) = {1, 0, 0, 0.4}; Point(3) = {1, 1, 0, 0.4}; Point(4) = {0, 1, 0, 0.4};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Physical Surface(1) = {1};\n";

// Runs `text` as `dir`/s.geo; with a format, then meshes and writes `file` as -2 -format does.
bool run(const testing::ScratchDir& dir, const std::string& text, const std::string& format = "",
         const std::string& file = "") {
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream printed;
  interp::Interpreter in(sources, diags, printed, {});
  const std::string script = dir / "s.geo";
  if (in.run_buffer(script, text) == interp::RunStatus::Errors) return false;
  if (format.empty()) return true;
  return interp::mesh_from_command_line(in, 2, file, format, script);
}

}  // namespace

TEST_CASE("save formats: Save by extension writes what -format writes by name") {
  std::set<std::string_view> seen;
  for (const io::OutputFormat& f : io::output_formats()) {
    if (!seen.insert(f.extension).second) continue;   // Save takes the first row of an extension
    CAPTURE(f.name);
    // The same file name in two folders: the ocean grids' title is the file's name.
    std::string name(f.default_file_name);
    if (name.empty()) name.append("out").append(f.extension);
    testing::ScratchDir by_save, by_name;
    REQUIRE(run(by_save, kSaveSquare + "Mesh 2;\nSave \"" + name + "\";\n"));
    REQUIRE(run(by_name, kSaveSquare, std::string(f.name), by_name / name));
    const std::string saved = testing::read_all(by_save / name);
    CHECK(!saved.empty());
    CHECK(saved == testing::read_all(by_name / name));
  }
}

TEST_CASE("save formats: the default -o name comes from the row") {
  for (const io::OutputFormat& f : io::output_formats()) {
    CAPTURE(f.name);
    testing::ScratchDir dir;
    REQUIRE(run(dir, kSaveSquare, std::string(f.name)));
    std::string expected(f.default_file_name);
    if (expected.empty()) expected.append("s").append(f.extension);
    CHECK(testing::read_all(dir / expected).size() > 0);
  }
}

namespace {

// Runs `text` as `dir`/s.geo, then meshes and writes `file` as `-2 -o file` does; the
// diagnostics' text, and whether meshing started (the mesh statistics were set).
struct CliRun {
  bool ok = false, meshed = false;
  std::string rendered;
};

CliRun run_cli(const testing::ScratchDir& dir, const std::string& text, const std::string& file) {
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream printed;
  interp::Interpreter in(sources, diags, printed, {});
  const std::string script = dir.path / "s.geo";
  CliRun r;
  if (in.run_buffer(script, text) != interp::RunStatus::Errors)
    r.ok = interp::mesh_from_command_line(in, 2, (dir.path / file).string(), "", script);
  r.meshed = in.options().number("Mesh.NbTriangles") > 0;
  r.rendered = diags.render_all();
  return r;
}

}  // namespace

TEST_CASE("save formats: checks before meshing: a name that picks no format, an ocean grid without depths") {
  testing::ScratchDir dir;
  CliRun bad = run_cli(dir, kSaveSquare, "mesh.foo");
  CHECK(!bad.ok);
  CHECK(!bad.meshed);   // refused before the mesh was made
  CHECK(bad.rendered.find("unknown file extension '.foo'") != std::string::npos);

  CliRun no_depth = run_cli(dir, kSaveSquare, "fort.14");
  CHECK(no_depth.ok);
  CHECK(no_depth.rendered.find("no Mesh.DepthField is set, so every depth in this fort14 file is 0") !=
        std::string::npos);
  CliRun with_depth = run_cli(dir, kSaveSquare + "Field[1] = MathEval; Field[1].F = \"50\"; Mesh.DepthField = 1;\n",
                              "hgrid.gr3");
  CHECK(with_depth.ok);
  CHECK(with_depth.rendered.find("output-without-depth") == std::string::npos);
  // UGRID has no depth column to fill: a depth variable is written only with a depth field.
  CliRun ugrid = run_cli(dir, kSaveSquare, "mesh.nc");
  CHECK(ugrid.ok);
  CHECK(ugrid.rendered.find("output-without-depth") == std::string::npos);

  // Save in a script: the warning at the Save statement's file name.
  const std::string saved = (dir.path / "saved.gr3").string();
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream printed;
  interp::Interpreter in(sources, diags, printed, {});
  REQUIRE(in.run_buffer((dir.path / "t.geo").string(), kSaveSquare + "Mesh 2;\nSave \"" + saved + "\";\n") !=
          interp::RunStatus::Errors);
  CHECK(diags.render_all().find("t.geo:5:6: warning: '" + saved + "': no Mesh.DepthField") != std::string::npos);
}

TEST_CASE("save formats: a Save writes the partitions the options ask for then") {
  testing::ScratchDir dir;
  // Set after Mesh 2: partitioned at the Save; set to 0 again: not partitioned.
  REQUIRE(run(dir, kSaveSquare + "Mesh 2;\nMesh.NbPartitions = 3;\nSave \"p3.msh\";\nMesh.NbPartitions = 2;\n"
                                 "Save \"p2.msh\";\nMesh.NbPartitions = 0;\nSave \"p0.msh\";\n"));
  CHECK(testing::read_all(dir / "p3.msh").find("$PartitionedEntities\n3\n0\n") != std::string::npos);
  CHECK(testing::read_all(dir / "p2.msh").find("$PartitionedEntities\n2\n0\n") != std::string::npos);
  CHECK(testing::read_all(dir / "p0.msh").find("$PartitionedEntities") == std::string::npos);
  // PartitionMesh N (Gmsh's statement) partitions the mesh there and sets the option.
  REQUIRE(run(dir, kSaveSquare + "Mesh 2;\nPartitionMesh 3;\nAssert(Mesh.NbPartitions == 3);\nSave \"pm3.msh\";\n"));
  CHECK(testing::read_all(dir / "pm3.msh") == testing::read_all(dir / "p3.msh"));
  // -part's way (the option before meshing) writes the same bytes as the Save's.
  testing::ScratchDir cli;
  REQUIRE(run(cli, kSaveSquare + "Mesh.NbPartitions = 3;\n", "msh", cli / "p3.msh"));
  CHECK(testing::read_all(cli / "p3.msh") == testing::read_all(dir / "p3.msh"));
}
