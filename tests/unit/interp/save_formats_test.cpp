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
