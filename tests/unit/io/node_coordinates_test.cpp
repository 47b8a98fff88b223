// Node coordinates of MSH/VTK files: lon/lat and stereographic values against the sphere's
// formulas, planar models, construction points, and files that Gmsh 4.8.4 loads with the
// same counts.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "geo/sphere.h"
#include "io/msh_writer.h"
#include "io/node_coordinates.h"
#include "io/test_meshes.h"
#include "io/vtk_writer.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

namespace {

constexpr double kR = 6371e3;
constexpr double kDeg = 3.14159265358979323846 / 180;

// The patch (lon -10..10, lat 40..50 on the Earth's sphere) plus the sphere's centre as a
// model point, as a PolarSphere script has it.
MeshModel patch_with_centre() {
  MeshModel m = sm::io::testing::sphere_patch(8, kR);
  m.xyz.push_back({0, 0, 0});
  EntityMesh p;
  p.dim = 0, p.tag = 9, p.type = ElementType::Point1;
  p.nodes = {static_cast<std::uint32_t>(m.xyz.size() - 1)};
  p.connectivity = p.nodes;
  m.entities.push_back(p);
  return m;
}


}  // namespace

TEST_CASE("node coordinates: lon/lat degrees from the sphere's formulas") {
  MeshModel m = patch_with_centre();
  const MeshModel before = m;
  REQUIRE(convert_node_coordinates(m, NodeCoordinates::LonLat, SphereFrame{{0, 0, 0}, kR}).empty());
  CHECK(validate_mesh_model(m).empty());
  // grid_square's node (i, j) of 8 x 8 is at lon -10 + 2.5 i, lat 40 + 1.25 j.
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      const Vec3 x = m.xyz[j * 9 + i];
      CHECK(x.x == doctest::Approx(-10 + 2.5 * i).epsilon(1e-12));
      CHECK(x.y == doctest::Approx(40 + 1.25 * j).epsilon(1e-12));
      CHECK(x.z == 0);
      // And back: X = R (cos lat cos lon, cos lat sin lon, sin lat).
      const Vec3 b = before.xyz[j * 9 + i];
      CHECK(b.x == doctest::Approx(kR * std::cos(x.y * kDeg) * std::cos(x.x * kDeg)));
      CHECK(b.z == doctest::Approx(kR * std::sin(x.y * kDeg)));
    }
  // The centre (a construction point) has no lon/lat: its Point entity is left out.
  CHECK(m.entities.size() == before.entities.size() - 1);
  for (const EntityMesh& e : m.entities) CHECK(e.tag != 9);
}

TEST_CASE("node coordinates: the stereographic plane is Gmsh's PolarSphere (u, v)") {
  MeshModel m = patch_with_centre();
  REQUIRE(convert_node_coordinates(m, NodeCoordinates::Stereographic, SphereFrame{{0, 0, 0}, kR}).empty());
  const geo::PolarSphere sphere({0, 0, 0}, kR);
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      const double lon = (-10 + 2.5 * i) * kDeg, lat = (40 + 1.25 * j) * kDeg;
      // u = -cos(lat) cos(lon) / (1 + sin(lat)), v the same with sin(lon).
      const Vec3 x = m.xyz[j * 9 + i];
      CHECK(x.x == doctest::Approx(-std::cos(lat) * std::cos(lon) / (1 + std::sin(lat))).epsilon(1e-12));
      CHECK(x.y == doctest::Approx(-std::cos(lat) * std::sin(lon) / (1 + std::sin(lat))).epsilon(1e-12));
      CHECK(x.z == 0);
      const Vec3 back = sphere.point({x.x, x.y});
      CHECK(norm(back - sm::io::testing::sphere_patch(8, kR).xyz[j * 9 + i]) < 1e-6);
    }
}

TEST_CASE("node coordinates: planar models, poles, nodes off the sphere, xyz unchanged") {
  MeshModel plane = sm::io::testing::grid_square(4);
  const MeshModel before = plane;
  const std::string why = convert_node_coordinates(plane, NodeCoordinates::LonLat, std::nullopt);
  CHECK(why.find("planar") != std::string::npos);
  CHECK(plane.xyz == before.xyz);
  CHECK(convert_node_coordinates(plane, NodeCoordinates::Stereographic, std::nullopt).empty());
  CHECK(plane.xyz == before.xyz);
  MeshModel sphere = sm::io::testing::sphere_patch(4, kR);
  CHECK(convert_node_coordinates(sphere, NodeCoordinates::Xyz, SphereFrame{{0, 0, 0}, kR}).empty());
  CHECK(sphere.xyz == sm::io::testing::sphere_patch(4, kR).xyz);
  // A triangle node at the south pole has no stereographic coordinates.
  sphere.xyz[12] = {0, 0, -kR};
  const std::string pole = convert_node_coordinates(sphere, NodeCoordinates::Stereographic, SphereFrame{{0, 0, 0}, kR});
  CHECK(pole.find("node 13 (lon 0.0000, lat -90.0000) lies at the pole") == 0);
  // A triangle node off the sphere is an error; the mesh is left as it was.
  MeshModel off = sm::io::testing::sphere_patch(4, kR);
  off.xyz[12] = off.xyz[12] * 1.01;
  const MeshModel off_before = off;
  CHECK(convert_node_coordinates(off, NodeCoordinates::LonLat, SphereFrame{{0, 0, 0}, kR}).find("node 13") == 0);
  CHECK(off.xyz == off_before.xyz);
  CHECK(off.entities.size() == off_before.entities.size());
}

TEST_CASE("node coordinates: MSH files in lon/lat and stereographic load in Gmsh with the same counts") {
  if (std::system("/usr/bin/python3 -c 'import gmsh' >/dev/null 2>&1") != 0) {
    MESSAGE("python3-gmsh not installed: skipped");
    return;
  }
  // A folder of this run's own: fixed /tmp names raced with the same test of other checkouts.
  const sm::testing::ScratchDir dir;
  const std::string script = (dir.path / "coords.py").string();
  // One Python run loads every file (starting Gmsh's module costs most of the time).
  std::ofstream(script)
      << "import sys, gmsh\n"
         "gmsh.initialize(['x', '-v', '0'])\n"
         "for path in sys.argv[1:]:\n"
         "    gmsh.clear()\n"
         "    gmsh.open(path)\n"
         "    tags, xyz, _ = gmsh.model.mesh.getNodes()\n"
         "    _, t2, _ = gmsh.model.mesh.getElements(2)\n"
         "    _, t1, _ = gmsh.model.mesh.getElements(1)\n"
         "    xs, ys, zs = xyz[0::3], xyz[1::3], xyz[2::3]\n"
         "    print(len(tags), sum(len(e) for e in t2), sum(len(e) for e in t1),\n"
         "          '%.6f %.6f %.6f %.6f %.6f' % (min(xs), max(xs), min(ys), max(ys), max(abs(z) for z in zs)))\n";
  const MeshModel xyz = sm::io::testing::sphere_patch(8, kR);
  std::string paths, want_all;
  for (NodeCoordinates mode : {NodeCoordinates::LonLat, NodeCoordinates::Stereographic}) {
    MeshModel m = xyz;
    REQUIRE(convert_node_coordinates(m, mode, SphereFrame{{0, 0, 0}, kR}).empty());
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Vec3& p : m.xyz)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    // 81 nodes, 128 triangles, 4 x 8 + 8 boundary and mid-curve segments.
    const std::string want = fmt::format("81 128 40 {:.6f} {:.6f} {:.6f} {:.6f} 0.000000\n", x0, x1, y0, y1);
    for (int version : {22, 41})
      for (bool binary : {false, true}) {
        const std::string path =
            (dir.path / fmt::format("coords_{}_{}_{}.msh", static_cast<int>(mode), version, binary)).string();
        std::string error;
        REQUIRE(save_msh(m, {version, binary, false, false}, path, &error));
        paths += " " + path;
        want_all += want;
      }
    if (mode == NodeCoordinates::LonLat) CHECK(want.find("81 128 40 -10.000000 10.000000 40.000000 50.000000") == 0);
    // VTK: the same points as written (legacy ASCII, z = 0 everywhere).
    std::string error;
    const std::string vtk_path = (dir.path / "coords.vtk").string();
    REQUIRE(save_vtk(m, {}, vtk_path, &error));
    const std::string vtk = sm::testing::read_all(vtk_path);
    CHECK(vtk.find("POINTS 81 double") != std::string::npos);
  }
  const std::string out = (dir.path / "coords.txt").string();
  REQUIRE(std::system(("/usr/bin/python3 " + script + paths + " > " + out).c_str()) == 0);
  CHECK(sm::testing::read_all(out) == want_all);
}
