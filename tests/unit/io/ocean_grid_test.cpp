// ADCIRC fort.14 and SCHISM hgrid.gr3/.ll: written, read back, and compared
// with what went in (lon/lat, depth, triangles, boundary strings).
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "geo/sphere.h"
#include "io/ocean_grid.h"
#include "io/test_meshes.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

namespace {


// The grid square mapped onto the unit sphere as a lon/lat patch
// (lon = 10 + 20 x, lat = 40 + 10 y), with depth = 100 + 50 x.
struct Patch {
  MeshModel mesh;
  OceanGridOptions opt;
};

Patch patch() {
  Patch p;
  p.mesh = sm::io::testing::grid_square(6);
  const geo::PolarSphere sphere({0, 0, 0}, 1);
  for (Vec3& x : p.mesh.xyz) {
    p.opt.depth.push_back(100 + 50 * x.x);
    x = sphere.from_lonlat({10 + 20 * x.x, 40 + 10 * x.y});
  }
  // Open boundary along the south edge (curve 1), mainland along the rest,
  // and one "island" made of the 4 nodes around the centre cell.
  auto id = [](int i, int j) { return static_cast<std::uint32_t>(j * 7 + i); };
  BoundaryString open{BoundaryString::Kind::Open, {}}, land{BoundaryString::Kind::Mainland, {}};
  for (int i = 0; i <= 6; ++i) open.nodes.push_back(id(i, 0));
  for (int j = 0; j <= 6; ++j) land.nodes.push_back(id(6, j));
  BoundaryString island{BoundaryString::Kind::Island, {id(3, 3), id(4, 3), id(4, 4), id(3, 4)}};
  p.opt.boundaries = {open, land, island};
  return p;
}

// A path in this run's own folder: fixed /tmp names raced with the same test of other
// checkouts running at once.
std::string ocean_grid_tmp(const char* name) {
  static const sm::testing::ScratchDir dir;
  return (dir.path / name).string();
}

}  // namespace

TEST_CASE("fort.14: round trip of nodes, depths, triangles and boundaries") {
  const Patch p = patch();
  std::string error;
  REQUIRE(save_fort14(p.mesh, p.opt, ocean_grid_tmp("sm_fort.14"), &error));
  OceanGrid g;
  REQUIRE(parse_ocean_grid(sm::testing::read_all(ocean_grid_tmp("sm_fort.14")), &g, &error));
  REQUIRE(g.xy.size() == 49);
  CHECK(g.triangles.size() == 72 * 3);
  // Node ids follow entity order (points, curves, surface), so find each
  // written node by its lon/lat.
  double max_err = 0;
  for (std::size_t i = 0; i < g.xy.size(); ++i) {
    const double x = (g.xy[i].x - 10) / 20;
    max_err = std::max(max_err, std::abs(g.depth[i] - (100 + 50 * x)));
  }
  CHECK(max_err < 1e-8);
  REQUIRE(g.open.size() == 1);
  CHECK(g.open[0].nodes.size() == 7);
  REQUIRE(g.land.size() == 2);
  CHECK(g.land[0].type == 20);
  CHECK(g.land[1].type == 21);
  CHECK(g.land[1].nodes.size() == 5);  // island closed: first node repeated
  CHECK(g.land[1].nodes.front() == g.land[1].nodes.back());
  for (std::uint32_t v : g.open[0].nodes) CHECK(std::abs(g.xy[v].y - 40) < 1e-9);
}

TEST_CASE("hgrid.gr3 and hgrid.ll: SCHISM flags, loops not repeated") {
  Patch p = patch();
  p.opt.lonlat = false;  // gr3 in the mesh's own coordinates, .ll in lon/lat
  std::string error;
  REQUIRE(save_schism(p.mesh, p.opt, ocean_grid_tmp("hgrid.gr3"), &error));
  OceanGrid gr3, ll;
  REQUIRE(parse_ocean_grid(sm::testing::read_all(ocean_grid_tmp("hgrid.gr3")), &gr3, &error));
  REQUIRE(parse_ocean_grid(sm::testing::read_all(ocean_grid_tmp("hgrid.ll")), &ll, &error));
  REQUIRE(gr3.land.size() == 2);
  CHECK(gr3.land[0].type == 0);
  CHECK(gr3.land[1].type == 1);
  CHECK(gr3.land[1].nodes.size() == 4);
  for (std::size_t i = 0; i < ll.xy.size(); ++i) {
    CHECK(ll.xy[i].x >= 10 - 1e-9);
    CHECK(ll.xy[i].x <= 30 + 1e-9);
    CHECK(std::abs(gr3.xy[i].x) <= 1.0);  // Cartesian on the unit sphere
  }
}

TEST_CASE("ocean grids: bad input is rejected with the line") {
  const Patch p = patch();
  std::string error;
  MeshModel lines_only = p.mesh;
  lines_only.entities.pop_back();  // drop the surface
  CHECK_FALSE(save_fort14(lines_only, {}, ocean_grid_tmp("sm_fort_bad.14"), &error));
  CHECK(error.find("no triangles") != std::string::npos);
  OceanGrid g;
  CHECK_FALSE(parse_ocean_grid("title\n2 3\n1 0 0 1\n2 1 0 1\n", &g, &error));
  CHECK(error == "line 5: unexpected end of file");
  CHECK_FALSE(parse_ocean_grid("title\n1 3\n1 0 0 1\n2 1 0 1\n3 0 1 1\n1 3 1 2 9\n", &g, &error));
  CHECK(error == "line 6: element node out of range");
  CHECK_FALSE(parse_ocean_grid("title\n-1 1e12\n", &g, &error));
  CHECK(error == "line 2: absurd element or node count");
}
