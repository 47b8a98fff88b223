// define-constant-ignored: a DefineConstant after the Include of a template that defined the
// name first is noted once, at the ignored entry, naming the kept value and where it came
// from; the intended order (the script's value before the Include), -setnumber presets,
// equal values and General.WarnOnIgnoredDefineConstant = 0 give no note.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "interp/interpreter.h"

namespace {

struct DciRun {
  std::string printed;
  std::vector<std::string> notes;   // the define-constant-ignored messages
};

DciRun dci_run(const std::string& main_text, double preset = -1) {
  // Its own folder (not scratch_dir.h: its sm::testing would clash with another test file's
  // `using namespace` in the same unity batch).
  static int runs = 0;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("sm_dci_" + std::to_string(::getpid()) + "_" + std::to_string(runs++));
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "tmpl.geo") << "DefineConstant[ Size = 1e3, Name = \"a\" ];\n"; }
  const std::string main = (dir / "main.geo").string();
  { std::ofstream(main) << main_text; }
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  std::ostringstream printed;
  sm::interp::RunSettings settings;
  settings.stdlib_dir = SM_SOURCE_DIR "/stdlib";   // the binary finds it beside itself
  sm::interp::Interpreter in(sources, diags, printed, settings);
  if (preset >= 0) REQUIRE(in.preset_number("Size", preset).empty());
  REQUIRE(in.run_file(main) == sm::interp::RunStatus::Ok);
  std::filesystem::remove_all(dir);
  DciRun r;
  r.printed = printed.str();
  for (const sm::lang::Diagnostic& d : diags.all())
    if (d.kind == sm::lang::Diag::DefineConstantIgnored) {
      const sm::lang::LineCol lc = sources.line_col(d.range.begin_loc());
      r.notes.push_back(std::to_string(lc.line) + ":" + std::to_string(lc.col) + " " + d.message);
    }
  return r;
}

}  // namespace

TEST_CASE("define-constant-ignored: after the template's Include, noted once with the kept value") {
  const DciRun r = dci_run(
      "Include \"tmpl.geo\";\n"
      "DefineConstant[ Size = 7e3, Name = \"b\" ];\n"
      "DefineConstant[ Size = 8e3 ];\n"
      "Printf(\"%g\", Size);\n");
  CHECK(r.printed == "1000\n");   // Gmsh's rule stands: the first definition wins
  REQUIRE(r.notes.size() == 2);
  CHECK(r.notes[0] ==
        "2:17 Size keeps 1000 from tmpl.geo:1; this value (7000) is ignored: set it before the Include "
        "(General.WarnOnIgnoredDefineConstant = 0 silences this)");
  CHECK(r.notes[1].find("Name keeps \"a\" from tmpl.geo:1; this value (\"b\") is ignored") != std::string::npos);
}

TEST_CASE("define-constant-ignored: the intended order, presets, equal values and the option say nothing") {
  CHECK(dci_run("DefineConstant[ Size = 7e3 ];\nInclude \"tmpl.geo\";\n").notes.empty());
  CHECK(dci_run("Include \"tmpl.geo\";\nDefineConstant[ Size = 7e3 ];\n", 5).notes.empty());
  CHECK(dci_run("Include \"tmpl.geo\";\nDefineConstant[ Size = 1000 ];\n").notes.empty());
  CHECK(dci_run("General.WarnOnIgnoredDefineConstant = 0;\nInclude \"tmpl.geo\";\nDefineConstant[ Size = 7e3 ];\n")
            .notes.empty());
  CHECK(dci_run("General.Verbosity = 4;\nInclude \"tmpl.geo\";\nDefineConstant[ Size = 7e3 ];\n").notes.empty());
  // The same file twice: not a template's default.
  CHECK(dci_run("DefineConstant[ Size = 1 ];\nDefineConstant[ Size = 2 ];\n").notes.empty());
}

TEST_CASE("define-constant-ignored: the tutorial's trap with the stdlib's ocean_fields.geo") {
  const DciRun r = dci_run("Include \"ocean_fields.geo\";\nDefineConstant[ ShoreSizeMin = 2e3 ];\n");
  REQUIRE(r.notes.size() == 1);
  CHECK(r.notes[0].find("ShoreSizeMin keeps 30000 from ocean_fields.geo:") != std::string::npos);
}
