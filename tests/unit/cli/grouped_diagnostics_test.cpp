// What the binary prints for a statement with many diagnostics (one group, cut, with
// the way to see all), -v 6, --diagnostics FILE, and -1's summary and --stats.
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "run_binary.h"
#include "scratch_dir.h"

namespace {

const std::string kWorldC = std::string(SM_SOURCE_DIR) + "/tests/readback/diagnostics_world_c.geo";

std::size_t count_of(const std::string& s, const std::string& needle) {
  std::size_t n = 0;
  for (auto p = s.find(needle); p != std::string::npos; p = s.find(needle, p + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("cli grouped diagnostics: one caret for the import's many warnings, cut, and whole at -v 6") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) return;
  const std::string err = sm::testing::run_output(bin + " -0 " + kWorldC, "2>&1 >/dev/null");
  INFO(err);
  CHECK(count_of(err, "loops[] = Coastline{1};") == 1);
  CHECK(count_of(err, "warnings from this statement: ") == 1);
  CHECK(err.find(" x islands merged across a strait narrower than the accuracy [coastline-repair]\n") !=
        std::string::npos);
  CHECK(err.find("not listed: -v 6 lists every one, --diagnostics FILE writes them as JSON lines)\n") !=
        std::string::npos);
  // Short: the group is a few lines per sort, not one diagnostic of three lines per change.
  CHECK(count_of(err, "\n") < 40);

  const std::string all = sm::testing::run_output(bin + " -0 -v 6 " + kWorldC, "2>&1 >/dev/null");
  CHECK(count_of(all, "loops[] = Coastline{1};") == 1);
  CHECK(all.find("not listed") == std::string::npos);
  CHECK(all.find("... and") == std::string::npos);
  CHECK(count_of(all, "\n") > count_of(err, "\n") + 50);
}

TEST_CASE("cli --diagnostics: one JSON line per diagnostic, every one, written beside and renamed") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) return;
  sm::testing::ScratchDir d;
  REQUIRE(sm::testing::run_status(bin + " -0 -v 0 " + kWorldC + " --diagnostics " + (d / "d.jsonl")) == 0);
  const std::string text = sm::testing::read_all(d / "d.jsonl");
  const std::string err = sm::testing::run_output(bin + " -0 " + kWorldC, "2>&1 >/dev/null");
  // The header's count ("111 warnings from this statement") is the number of warning lines
  // (the import's deviation note is a line of its own).
  CHECK(err.find(": warning: " + std::to_string(count_of(text, "\"severity\": \"warning\"")) +
                 " warnings from this statement: ") != std::string::npos);
  CHECK(count_of(text, "{\"file\": ") == count_of(text, "\n"));
  CHECK(count_of(text, "\"lon\": ") > 50);
  CHECK(d.names() == std::vector<std::string>{"d.jsonl"});
  // A path that cannot be written: an error, exit status 1, nothing left behind.
  CHECK(sm::testing::run_status(bin + " -0 -v 0 " + kWorldC + " --diagnostics " + (d / "no/such/dir.jsonl")) == 1);
  CHECK(sm::testing::run_status(bin + " -0 --diagnostics") == 2);
}

TEST_CASE("cli -1: the 1D summary in km on the sphere, and --stats with the same figures") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) return;
  sm::testing::ScratchDir d;
  const std::string err = sm::testing::run_output(
      bin + " -1 " + kWorldC + " -o " + (d / "c.msh") + " --stats " + (d / "s.json"), "2>&1 >/dev/null");
  INFO(err);
  const auto m = err.find("\nMesh: ");
  REQUIRE(m != std::string::npos);
  const std::string line = err.substr(m + 1, err.find('\n', m + 1) - m - 1);
  CHECK(line.find(" nodes, ") != std::string::npos);
  CHECK(line.find(" line elements on ") != std::string::npos);
  CHECK(line.find(" km on the sphere") != std::string::npos);
  CHECK(err.find("\nTime: ") != std::string::npos);
  const std::string json = sm::testing::read_all(d / "s.json");
  CHECK(json.find("\"line_elements\": ") != std::string::npos);
  CHECK(json.find("\"edge_units\": \"m\"") != std::string::npos);
  CHECK(json.find("\"1D\": ") != std::string::npos);
  // The figures printed are the JSON's: the node count in both.
  const std::string nodes = line.substr(6, line.find(' ', 6) - 6);
  CHECK(json.find("{\"nodes\": " + nodes + ",") == 0);
}
