// VTK writers: structure checked in C++, and every variant read back by an
// independent reader (meshio) with the same counts and data.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/test_meshes.h"
#include "io/vtk_writer.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

TEST_CASE("vtk legacy ASCII: header, counts, cell types") {
  const MeshModel m = sm::io::testing::grid_square(4);
  const std::string s = vtk_to_string(m, {});
  CHECK(s.rfind("# vtk DataFile Version 3.0\n", 0) == 0);
  CHECK(s.find("POINTS 25 double\n") != std::string::npos);
  CHECK(s.find("CELLS 32 128\n") != std::string::npos);
  CHECK(s.find("CELL_TYPES 32\n5\n") != std::string::npos);
  CHECK(s.find("SCALARS quality_rho double 1") != std::string::npos);
}

TEST_CASE("vtk: every variant reads back in meshio with the same data") {
  if (std::system("/usr/bin/python3 -c 'import meshio' >/dev/null 2>&1") != 0) {
    MESSAGE("python3-meshio not installed: skipped");
    return;
  }
  const MeshModel m = sm::io::testing::grid_square(10);
  std::vector<double> size(m.xyz.size());
  for (std::size_t i = 0; i < size.size(); ++i) size[i] = 0.1 + m.xyz[i].x;
  // A folder of its own: parallel test runs (other build folders) must not share files.
  const sm::testing::ScratchDir dir;
  const std::string script = dir / "load.py";
  std::ofstream(script) << "import sys, meshio\n"
                           "m = meshio.read(sys.argv[1])\n"
                           "tri = sum(len(c.data) for c in m.cells if c.type == 'triangle')\n"
                           "h = m.point_data['size']\n"
                           "q = m.cell_data['quality_rho'][0]\n"
                           "print(len(m.points), tri, '%.6f' % h.sum(), '%.6f' % q.min())\n";
  for (bool xml : {false, true})
    for (bool binary : {false, true}) {
      const std::string path = dir / fmt::format("{}.{}", binary ? "bin" : "ascii", xml ? "vtu" : "vtk");
      const std::string out = dir / "out.txt";
      std::string error;
      REQUIRE(save_vtk(m, {xml, binary, false, {{"size", "m", "", size}}}, path, &error));
      REQUIRE(std::system(fmt::format("/usr/bin/python3 {} {} > {}", script, path, out).c_str()) == 0);
      std::ifstream in(out);
      std::stringstream got;
      got << in.rdbuf();
      CAPTURE(path);
      // 121 nodes; sum of 0.1 + x over the grid = 121 * 0.1 + 11 * (0 + 0.1 + ... + 1) = 12.1 + 60.5
      CHECK(got.str() == fmt::format("121 200 {:.6f} {:.6f}\n", 72.6, 2 * (std::sqrt(2.0) - 1)));
    }
}

TEST_CASE("vtk: node data of the wrong length is an error, nothing written") {
  const MeshModel m = sm::io::testing::grid_square(2);
  const sm::testing::ScratchDir dir;
  std::string error;
  CHECK_FALSE(save_vtk(m, {false, false, false, {{"size", "m", "", {1.0, 2.0}}}}, dir / "bad.vtk", &error));
  CHECK(dir.names().empty());
  CHECK(error.find("node data 'size' has 2 values for 9 nodes") != std::string::npos);
}
