// Progress through the interpreter: a recording sink in the kernel state sees
// the coastline import, 1D and 2D stages with non-decreasing updates, and nothing once
// the script sets General.Verbosity below 4.
#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "base/progress.h"
#include "interp/interpreter.h"

using namespace sm;

namespace {

struct Stage {
  std::string name;
  std::uint64_t total = 0;
  std::vector<std::uint64_t> updates;
  bool ended = false;
};

class RecordingProgress final : public Progress {
 public:
  std::vector<Stage> stages;
  bool nested = false;   // begin while a stage was open
  bool stray = false;    // update or end with no stage open
  void begin(std::string_view name, std::uint64_t total) override {
    nested = nested || !open_.empty();
    stages.push_back({std::string(name), total, {}, false});
    open_.push_back(stages.size() - 1);
  }
  void update(std::uint64_t done) override {
    if (open_.empty()) stray = true;
    else stages[open_.back()].updates.push_back(done);
  }
  void end() override {
    if (open_.empty()) stray = true;
    else stages[open_.back()].ended = true, open_.pop_back();
  }

 private:
  std::vector<std::size_t> open_;   // open stages, innermost last
};

struct Run {
  bool ok = false;
  std::string rendered;
};

Run run_with(const std::string& text, Progress* p) {
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream out;
  interp::Interpreter in(sources, diags, out, {});
  in.kernel().progress = p;
  in.run_buffer("progress.geo", text);
  return {diags.error_count() == 0, diags.render_all()};
}

void check_stage(const Stage& s) {
  CAPTURE(s.name);
  CHECK(s.ended);
  for (std::size_t i = 1; i < s.updates.size(); ++i) CHECK(s.updates[i] >= s.updates[i - 1]);
  if (s.total > 0) {
    REQUIRE(!s.updates.empty());
    CHECK(s.updates.back() == s.total);
  }
}

const char* const kSquareMesh =
    "Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
    "Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
    "Point(5) = {2, 0, 0, 0.1}; Point(6) = {3, 0, 0, 0.1}; Point(7) = {2, 1, 0, 0.1};\n"
    "Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};\n"
    "Curve Loop(2) = {5, 6, 7}; Plane Surface(2) = {2};\n";

}  // namespace

TEST_CASE("progress: 1D one unit per curve, then 2D, every stage ended") {
  RecordingProgress p;
  const Run r = run_with(std::string(kSquareMesh) + "Mesh 2;\n", &p);
  INFO(r.rendered);
  REQUIRE(r.ok);
  CHECK_FALSE(p.nested);
  CHECK_FALSE(p.stray);
  std::vector<std::string> names;
  for (const Stage& s : p.stages) names.push_back(s.name), check_stage(s);
  // 1D first; 2D reports its own units (faces today, parts of faces with threads).
  REQUIRE(names.size() >= 3);
  CHECK(names[0] == "1D");
  CHECK(names[1] == "1D repair");
  CHECK(std::find(names.begin(), names.end(), "2D") != names.end());
  CHECK(p.stages[0].total == 7);
  CHECK(p.stages[0].updates == std::vector<std::uint64_t>{1, 2, 3, 4, 5, 6, 7});
}

TEST_CASE("progress: a face refined in parts nests '2D refine' inside '2D', one unit per part") {
  // lc 0.003 on the unit square: about 250k triangles, above the 200k at which a face is
  // refined in parts.
  RecordingProgress p;
  const Run r = run_with(
      "Point(1) = {0, 0, 0, 0.003}; Point(2) = {1, 0, 0, 0.003};\n"
      "Point(3) = {1, 1, 0, 0.003}; Point(4) = {0, 1, 0, 0.003};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
      "General.NumThreads = 2;\n"
      "Mesh 2;\n",
      &p);
  INFO(r.rendered);
  REQUIRE(r.ok);
  CHECK_FALSE(p.stray);
  CHECK(p.nested);
  std::size_t at = p.stages.size();
  for (std::size_t i = 0; i < p.stages.size(); ++i) {
    check_stage(p.stages[i]);
    if (p.stages[i].name == "2D refine") at = i;
  }
  REQUIRE(at < p.stages.size());
  REQUIRE(at > 0);
  CHECK(p.stages[at - 1].name == "2D");
  // The parts: the power of two nearest 250k / 131072, at least 2.
  CHECK(p.stages[at].total >= 2);
  CHECK(p.stages[at].updates.front() == 0);
}

TEST_CASE("progress: silent below General.Verbosity 4, and without a sink") {
  RecordingProgress p;
  REQUIRE(run_with("General.Verbosity = 3;\n" + std::string(kSquareMesh) + "Mesh 2;\n", &p).ok);
  CHECK(p.stages.empty());
  REQUIRE(run_with(std::string(kSquareMesh) + "Mesh 2;\n", nullptr).ok);
}

TEST_CASE("progress: a failing 1D mesh still ends its stage") {
  // Two triangles whose edges cross: the 1D repair reports the crossing curves.
  RecordingProgress p;
  const Run r = run_with(
      "Point(1) = {0, 0, 0, 0.5}; Point(2) = {2, 0, 0, 0.5}; Point(3) = {1, 2, 0, 0.5};\n"
      "Point(4) = {0, 1, 0, 0.5}; Point(5) = {2, 1, 0, 0.5}; Point(6) = {1, -1, 0, 0.5};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
      "Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 4};\n"
      "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n"
      "Curve Loop(2) = {4, 5, 6}; Plane Surface(2) = {2};\n"
      "Mesh 2;\n",
      &p);
  CHECK_FALSE(r.ok);
  CHECK_FALSE(p.stray);
  REQUIRE(!p.stages.empty());
  for (const Stage& s : p.stages) CHECK(s.ended);
}

TEST_CASE("progress: coastline import on real data, one unit per pipeline step") {
  const std::string data = SM_DATA_DIR;
  RecordingProgress p;
  const Run r = run_with(
      "Point(1) = {0, 0, 0}; Point(2) = {0, 0, 6371009};\n"
      "PolarSphere(1) = {1, 2};\n"
      "Field[1] = MathEval; Field[1].F = \"20000\";\n"
      "Coastline[1] = LonLatText;\n"
      "Coastline[1].FileName = \"" + data + "/gshhg/gb_ireland_f.txt\";\n"
      "Coastline[1].AccuracyField = 1;\n"
      "Coastline[1].Region = {-9, -3, 50.5, 55};\n"
      "loops[] = Coastline{1};\n",
      &p);
  INFO(r.rendered);
  REQUIRE(r.ok);
  REQUIRE(p.stages.size() == 1);
  CHECK(p.stages[0].name == "coastline");
  CHECK(p.stages[0].total == 8);
  CHECK(p.stages[0].updates == std::vector<std::uint64_t>{1, 2, 3, 4, 5, 6, 7, 8});
  check_stage(p.stages[0]);
}
