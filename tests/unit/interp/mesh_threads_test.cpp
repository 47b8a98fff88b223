// -nt / General.NumThreads / Mesh.MaxNumThreads2D through a script: a face large enough
// to be refined in parts (mesh/partition.h) is written as the same .msh bytes whatever
// the thread count.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "interp_test_util.h"
#include "scratch_dir.h"

using sm::interp::testing::run_script;

namespace {


}  // namespace

TEST_CASE("mesh threads: General.NumThreads 1 and 2 and Mesh.MaxNumThreads2D 4 write the same .msh") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_mesh_threads_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A square with a hole at lc 0.0025: about 350k triangles, above the 200k estimate
  // from which mesh2d refines a face in parts.
  std::string script =
      "lc = 0.0025;\n"
      "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Point(5) = {0.3, 0.3, 0, lc}; Point(6) = {0.5, 0.3, 0, lc}; Point(7) = {0.4, 0.5, 0, lc};\n"
      "Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7};\n"
      "Plane Surface(1) = {1, 2};\n"
      "Mesh.Algorithm = 5;\n";
  const char* runs[][2] = {{"General.NumThreads = 1;", "a.msh"},
                           {"General.NumThreads = 2;", "b.msh"},
                           {"General.NumThreads = 1; Mesh.MaxNumThreads2D = 4;", "c.msh"}};
  for (const auto& run : runs)
    script += std::string(run[0]) + "\nMesh 2;\nPrintf(\"%g\", Mesh.NbTriangles);\nSave \"" + (dir / run[1]).string() +
              "\";\n";
  const auto r = run_script(script);
  INFO(r.rendered);
  REQUIRE(r.ok);
  std::istringstream counts(r.out);
  int n = 0, first = 0;
  for (int i = 0; i < 3; ++i) {
    REQUIRE(static_cast<bool>(counts >> n));
    if (i == 0) first = n;
    CHECK(n == first);
  }
  CHECK(first > 250000);
  const std::string a = sm::testing::read_all(dir / "a.msh");
  REQUIRE(a.size() > 1000000);
  CHECK(sm::testing::read_all(dir / "b.msh") == a);
  CHECK(sm::testing::read_all(dir / "c.msh") == a);
  fs::remove_all(dir);
}
