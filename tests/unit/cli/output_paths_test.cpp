// What `-o PATH` and `--stats PATH` do with the paths a user gives: standard
// output, symbolic links, devices, and the two files of SCHISM's grid.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "run_binary.h"
#include "scratch_dir.h"

namespace fs = std::filesystem;
using sm::testing::read_all;
using sm::testing::run_output;
using sm::testing::ScratchDir;
using sm::testing::run_status;
using sm::testing::stereomesh_binary;

namespace {

// A scratch directory holding square.geo: a unit square with a Printf and physical groups.
struct SquareDir : ScratchDir {
  SquareDir() {
    std::ofstream(path / "square.geo") << "Printf(\"hello\");\n"
                                          "Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2};\n"
                                          "Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};\n"
                                          "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                                          "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                                          "Physical Curve(\"coast\") = {1, 2, 3, 4}; Physical Surface(1) = {1};\n";
  }
};

}  // namespace

TEST_CASE("cli output: '-o -' writes the mesh to stdout, Printf to stderr") {
  const std::string bin = stereomesh_binary();
  if (bin.empty()) return;
  SquareDir d;
  const std::string out = run_output(bin + " -2 -v 0 " + (d / "square.geo") + " -o -", "2>/dev/null");
  CHECK(out.rfind("$MeshFormat\n4.1 0 8\n", 0) == 0);
  CHECK(out.find("$EndElements") != std::string::npos);
  CHECK(out.find("hello") == std::string::npos);
  const std::string err = run_output(bin + " -2 -v 0 " + (d / "square.geo") + " -o -", "2>&1 >/dev/null");
  CHECK(err == "hello\n");
  // hgrid.gr3 comes with hgrid.ll: standard output cannot hold both.
  CHECK(run_status(bin + " -2 -v 0 -format gr3 " + (d / "square.geo") + " -o -") == 1);
}

TEST_CASE("cli output: a link keeps pointing at its file; a device is not replaced") {
  const std::string bin = stereomesh_binary();
  if (bin.empty()) return;
  SquareDir d;
  std::ofstream(d / "real.msh") << "old";
  fs::create_symlink("real.msh", d / "link.msh");
  REQUIRE(run_status(bin + " -2 -v 0 " + (d / "square.geo") + " -o " + (d / "link.msh")) == 0);
  CHECK(fs::is_symlink(d / "link.msh"));
  CHECK(read_all(d / "real.msh").rfind("$MeshFormat", 0) == 0);

  const std::string err = run_output(bin + " -2 -v 0 " + (d / "square.geo") + " -o /dev/full", "2>&1 >/dev/null");
  CHECK(err.find("cannot write '/dev/full': No space left on device") != std::string::npos);
  CHECK(run_status(bin + " -2 -v 0 " + (d / "square.geo") + " -o /dev/full") == 1);
  struct stat st {};
  REQUIRE(::stat("/dev/full", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  CHECK(run_status(bin + " -2 -v 0 " + (d / "square.geo") + " --stats /dev/null -o /dev/null") == 0);
}

TEST_CASE("cli output: hgrid.gr3 and hgrid.ll are written together or not at all") {
  const std::string bin = stereomesh_binary();
  if (bin.empty()) return;
  SquareDir d;
  std::ofstream(d / "hgrid.gr3") << "old gr3\n";
  fs::create_directory(d / "hgrid.ll");   // hgrid.ll cannot be written
  CHECK(run_status(bin + " -2 -v 0 -format gr3 " + (d / "square.geo") + " -o " + (d / "hgrid.gr3")) == 1);
  CHECK(read_all(d / "hgrid.gr3") == "old gr3\n");
  CHECK(std::distance(fs::directory_iterator(d.path), {}) == 3);   // square.geo, hgrid.gr3, hgrid.ll/
  fs::remove(d / "hgrid.ll");
  CHECK(run_status(bin + " -2 -v 0 -format gr3 " + (d / "square.geo") + " -o " + (d / "hgrid.gr3")) == 0);
  CHECK(read_all(d / "hgrid.gr3") != "old gr3\n");
  CHECK(fs::file_size(d / "hgrid.ll") > 100);
}
