// The run's time account: the clock charges each interval to the innermost open stage
// (the script's evaluation when none is), so the stages add up to the elapsed time; a
// run names the field set-up, 1D, the 2D mesher's stages, the statistics and the writing.
#include <unistd.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "interp/interpreter.h"
#include "interp/kernel/mesh_commands.h"
#include "interp/stage_clock.h"

using namespace sm;
using namespace sm::interp;

namespace {

double stage_seconds(const std::vector<StageTime>& stages, const std::string& name) {
  for (const StageTime& t : stages)
    if (t.name == name) return t.seconds;
  return -1;
}

std::vector<std::string> stage_names(const std::vector<StageTime>& stages) {
  std::vector<std::string> out;
  for (const StageTime& t : stages) out.push_back(t.name);
  return out;
}

}  // namespace

TEST_CASE("stage clock: nested stages are exclusive, a stage run twice is one entry, the sum is the elapsed time") {
  double now = 10;
  StageClock c("script", [&] { return now; });
  now = 11;                    // script 1
  c.begin("import", 8);
  now = 14;                    // import 3
  c.begin("fields", 0);
  now = 14.5;                  // fields 0.5 (not import's)
  c.end();
  now = 15;                    // import 0.5 more
  c.end();
  now = 17;                    // script 2 more
  c.begin("fields", 0);
  now = 17.25;                 // fields again: the same entry
  c.end();
  c.end();                     // the base stays open
  now = 18;                    // script 0.75 more
  const std::vector<StageTime> s = c.stages();
  CHECK(stage_names(s) == std::vector<std::string>{"script", "import", "fields"});
  CHECK(stage_seconds(s, "script") == doctest::Approx(3.75));
  CHECK(stage_seconds(s, "import") == doctest::Approx(3.5));
  CHECK(stage_seconds(s, "fields") == doctest::Approx(0.75));
  CHECK(c.elapsed() == doctest::Approx(8));
  // An open stage is charged up to now.
  c.begin("writing", 0);
  now = 19;
  CHECK(stage_seconds(c.stages(), "writing") == doctest::Approx(1));
  CHECK(format_time_line(c.stages()) ==
        "Time: script 3.750 s, import 3.500 s, fields 0.750 s, writing 1.000 s, total 9.000 s\n");
}

TEST_CASE("stage clock: small field kinds are summed into 'fields', large ones keep their names") {
  const std::vector<StageTime> in = {{"script", 1}, {"field Box", 0.01}, {"fields", 0.02},
                                     {"field Distance", 0.5}, {"field MathEval", 0.03}, {"1D", 2}};
  const std::vector<StageTime> out = fold_small_stages(in, "field ", 0.1, "fields");
  CHECK(stage_names(out) == std::vector<std::string>{"script", "fields", "field Distance", "1D"});
  CHECK(stage_seconds(out, "fields") == doctest::Approx(0.06));
  double sum_in = 0, sum_out = 0;
  for (const StageTime& t : in) sum_in += t.seconds;
  for (const StageTime& t : out) sum_out += t.seconds;
  CHECK(sum_out == doctest::Approx(sum_in));
  // Without a "fields" stage, one is made where the first small kind was.
  CHECK(stage_names(fold_small_stages({{"script", 1}, {"field Box", 0.01}}, "field ", 0.1, "fields")) ==
        std::vector<std::string>{"script", "fields"});
}

TEST_CASE("stage clock: a meshing run's account names every stage and adds up to the interpreter's time") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_stage_clock_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream out;
  Interpreter in(sources, diags, out, {});
  in.run_buffer((dir / "clock.geo").string(),
                "General.Verbosity = 0;\n"
                "Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
                "Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};\n"
                "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                "Field[1] = Box; Field[1].VIn = 0.05; Field[1].VOut = 0.1; Field[1].XMax = 0.5;\n"
                "Field[1].YMax = 1; Background Field = 1;\n"
                "Mesh 2;\n"
                "Save \"clock.msh\";\n");
  INFO(diags.render_all());
  REQUIRE(diags.error_count() == 0);
  const std::vector<StageTime> s = run_stages(in);
  const std::vector<std::string> names = stage_names(s);
  CAPTURE(format_time_line(s));
  REQUIRE(!names.empty());
  CHECK(names.front() == "script");
  for (const char* want : {"fields", "1D", "2D boundary", "2D refine", "statistics", "writing"})
    CHECK(std::find(names.begin(), names.end(), want) != names.end());
  // The Box's set-up is far under 0.1 s: in "fields", not on its own.
  CHECK(std::find(names.begin(), names.end(), "field Box") == names.end());
  CHECK(std::find(names.begin(), names.end(), "2D") == names.end());   // shown by its parts
  double sum = 0;
  for (const StageTime& t : s) {
    CHECK(t.seconds >= 0);
    sum += t.seconds;
  }
  // (the 2D mesher's time outside its stages is left out under half a millisecond)
  CHECK(std::abs(sum - in.kernel().clock.elapsed()) < 0.002);
  // The statistics JSON carries the same stages.
  const std::string json = finish_run(in);
  CHECK(json.find("\"statistics\": ") != std::string::npos);
  CHECK(json.find("\"writing\": ") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("stage clock: the CPU account charges the same stages with the CPU clock's seconds") {
  double now = 0, cpu = 100;
  StageClock c("script", [&] { return now; }, [&] { return cpu; });
  now = 1, cpu = 100.5;        // script: 1 s wall, 0.5 s CPU
  c.begin("2D", 0);
  now = 2, cpu = 102.5;        // 2D: 1 s wall, 2 s CPU (two threads)
  c.end();
  now = 4, cpu = 103;          // script again: the open base is charged up to now
  const std::vector<StageTime> wall = c.stages(), used = c.cpu_stages();
  CHECK(stage_names(used) == stage_names(wall));
  CHECK(stage_seconds(wall, "2D") == doctest::Approx(1));
  CHECK(stage_seconds(used, "2D") == doctest::Approx(2));
  CHECK(stage_seconds(used, "script") == doctest::Approx(1));
}
