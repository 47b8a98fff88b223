// Printf > file and >> file: written through the one output writer, put in
// place when the run ends without errors, readable by a later Include.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "interp_test_util.h"
#include "scratch_dir.h"

namespace fs = std::filesystem;
using sm::interp::testing::run_script;
using sm::testing::read_all;
using sm::testing::ScratchDir;

TEST_CASE("Printf redirection: > starts the file, >> continues it, one file at the end") {
  ScratchDir d;
  std::ofstream((d / "log.txt")) << "before\n";
  const auto r = run_script("f = \"" + (d / "log.txt") + "\";\n"
                            "Printf(\"first\") >> f;\n"
                            "For i In {1:3}\n  Printf(\"line %g\", i) >> f;\nEndFor\n"
                            "Printf(\"new\") > \"" + (d / "new.txt") + "\";\n"
                            "Printf(\"again\") > \"" + (d / "new.txt") + "\";\n");
  REQUIRE(r.ok);
  CHECK(read_all((d / "log.txt")) == "before\nfirst\nline 1\nline 2\nline 3\n");
  CHECK(read_all((d / "new.txt")) == "again\n");
  CHECK(d.names().size() == 2);
}

TEST_CASE("Printf redirection: a script that fails writes no file") {
  ScratchDir d;
  std::ofstream((d / "out.txt")) << "old\n";
  const auto r = run_script("Printf(\"partial\") > \"" + (d / "out.txt") + "\";\n"
                            "Printf(\"new\") > \"" + (d / "fresh.txt") + "\";\n"
                            "x = 1 / 0;\n");
  CHECK_FALSE(r.ok);
  CHECK(read_all((d / "out.txt")) == "old\n");
  CHECK_FALSE(fs::exists((d / "fresh.txt")));
  CHECK(d.names().size() == 1);
}

TEST_CASE("Printf redirection: a written .geo can be included by the same script") {
  ScratchDir d;
  const auto r = run_script("Printf(\"y = 42;\") > \"" + (d / "gen.geo") + "\";\n"
                            "Include \"" + (d / "gen.geo") + "\";\n"
                            "Printf(\"%g\", y);\n");
  REQUIRE(r.ok);
  CHECK(r.out == "42\n");
}

TEST_CASE("Printf redirection: a full device is a located error at the file name") {
  const auto r = run_script("Printf(\"x\") > \"/dev/full\";\n");
  CHECK_FALSE(r.ok);
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "1:15 file-write-error");
  CHECK(r.rendered.find("cannot write '/dev/full': No space left on device") != std::string::npos);
}
