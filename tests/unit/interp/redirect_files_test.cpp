// Printf > file and >> file: written through the one output writer, put in
// place when the run ends without errors, readable by a later Include.
#include <doctest/doctest.h>

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "interp_test_util.h"

namespace fs = std::filesystem;
using sm::interp::testing::run_script;

namespace {

struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::string t = (fs::temp_directory_path() / "sm-redirect-XXXXXX").string();
    REQUIRE(::mkdtemp(t.data()) != nullptr);
    path = t;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::size_t count() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(path), {})); }
};

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("Printf redirection: > starts the file, >> continues it, one file at the end") {
  ScratchDir d;
  std::ofstream(d.file("log.txt")) << "before\n";
  const auto r = run_script("f = \"" + d.file("log.txt") + "\";\n"
                            "Printf(\"first\") >> f;\n"
                            "For i In {1:3}\n  Printf(\"line %g\", i) >> f;\nEndFor\n"
                            "Printf(\"new\") > \"" + d.file("new.txt") + "\";\n"
                            "Printf(\"again\") > \"" + d.file("new.txt") + "\";\n");
  REQUIRE(r.ok);
  CHECK(read_all(d.file("log.txt")) == "before\nfirst\nline 1\nline 2\nline 3\n");
  CHECK(read_all(d.file("new.txt")) == "again\n");
  CHECK(d.count() == 2);
}

TEST_CASE("Printf redirection: a script that fails writes no file") {
  ScratchDir d;
  std::ofstream(d.file("out.txt")) << "old\n";
  const auto r = run_script("Printf(\"partial\") > \"" + d.file("out.txt") + "\";\n"
                            "Printf(\"new\") > \"" + d.file("fresh.txt") + "\";\n"
                            "x = 1 / 0;\n");
  CHECK_FALSE(r.ok);
  CHECK(read_all(d.file("out.txt")) == "old\n");
  CHECK_FALSE(fs::exists(d.file("fresh.txt")));
  CHECK(d.count() == 1);
}

TEST_CASE("Printf redirection: a written .geo can be included by the same script") {
  ScratchDir d;
  const auto r = run_script("Printf(\"y = 42;\") > \"" + d.file("gen.geo") + "\";\n"
                            "Include \"" + d.file("gen.geo") + "\";\n"
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
