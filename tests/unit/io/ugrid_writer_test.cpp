// UGRID netCDF: the bytes ugrid_to_bytes builds, opened again by netCDF from memory and
// checked against what went in (counts, anticlockwise faces, the fill of mixed faces,
// boundary edges only, their kinds and groups, depths, the atomic save).
#include <doctest/doctest.h>
#include <netcdf.h>
#include <netcdf_mem.h>

#include <cmath>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include "geo/sphere.h"
#include "io/test_meshes.h"
#include "io/ugrid_writer.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

namespace {

// A netCDF file opened from bytes, with the few reads the checks need.
struct UgridRead {
  int id = -1;
  explicit UgridRead(std::string& bytes) {
    REQUIRE(nc_open_mem("t.nc", NC_NOWRITE, bytes.size(), bytes.data(), &id) == NC_NOERR);
  }
  ~UgridRead() { nc_close(id); }
  std::size_t dim(const char* name) const {
    int d = -1;
    std::size_t n = 0;
    if (nc_inq_dimid(id, name, &d) != NC_NOERR) return 0;
    nc_inq_dimlen(id, d, &n);
    return n;
  }
  bool has(const char* var) const {
    int v = -1;
    return nc_inq_varid(id, var, &v) == NC_NOERR;
  }
  template <class T>
  std::vector<T> values(const char* var, std::size_t n) const {
    int v = -1;
    REQUIRE(nc_inq_varid(id, var, &v) == NC_NOERR);
    std::vector<T> out(n);
    if constexpr (std::is_same_v<T, int>)
      REQUIRE(nc_get_var_int(id, v, out.data()) == NC_NOERR);
    else
      REQUIRE(nc_get_var_double(id, v, out.data()) == NC_NOERR);
    return out;
  }
  std::vector<int> ints(const char* var, std::size_t n) const { return values<int>(var, n); }
  std::vector<double> doubles(const char* var, std::size_t n) const { return values<double>(var, n); }
  std::string text(const char* var, const char* att) const {
    int v = NC_GLOBAL;
    if (*var) REQUIRE(nc_inq_varid(id, var, &v) == NC_NOERR);
    std::size_t n = 0;
    if (nc_inq_attlen(id, v, att, &n) != NC_NOERR) return {};
    std::string s(n, '\0');
    nc_get_att_text(id, v, att, s.data());
    return s;
  }
};

}  // namespace

TEST_CASE("UGRID: a sphere patch with half its triangles clockwise, an open side and an inner curve") {
  MeshModel m = sm::io::testing::sphere_patch(4, 6371e3);
  for (EntityMesh& e : m.entities)
    if (e.dim == 2)
      for (std::size_t i = 0; i < e.connectivity.size(); i += 6)
        std::swap(e.connectivity[i + 1], e.connectivity[i + 2]);
  OceanGridOptions opt;
  opt.radius = 6371e3;
  opt.lonlat = true;
  opt.title = "patch";
  // The south side (curve 1, y = 0) open.
  opt.boundaries.push_back({BoundaryString::Kind::Open, {0, 1, 2, 3, 4}});
  for (std::size_t v = 0; v < m.xyz.size(); ++v) opt.depth.push_back(10.0 * static_cast<double>(v));
  std::string error;
  std::string bytes = ugrid_to_bytes(m, opt, &error);
  REQUIRE_MESSAGE(!bytes.empty(), error);
  UgridRead nc(bytes);
  CHECK(nc.text("mesh2d", "cf_role") == "mesh_topology");
  CHECK(nc.text("", "Conventions") == "CF-1.8 UGRID-1.0");
  REQUIRE(nc.dim("mesh2d_nNodes") == 25);
  REQUIRE(nc.dim("mesh2d_nFaces") == 32);
  CHECK(nc.dim("mesh2d_nMax_face_nodes") == 3);
  // The four sides' 16 edges; the inner curve at lat 45 has faces on both sides.
  REQUIRE(nc.dim("mesh2d_nEdges") == 16);

  const std::vector<double> lon = nc.doubles("mesh2d_node_x", 25), lat = nc.doubles("mesh2d_node_y", 25);
  CHECK(lon[0] == doctest::Approx(-10));
  CHECK(lat[0] == doctest::Approx(40));
  CHECK(lon[24] == doctest::Approx(10));
  CHECK(lat[24] == doctest::Approx(50));
  const std::vector<double> depth = nc.doubles("mesh2d_node_depth", 25);
  CHECK(depth[24] == 240.0);
  CHECK(nc.text("mesh2d_node_depth", "positive") == "down");

  const std::vector<int> faces = nc.ints("mesh2d_face_nodes", 32 * 3);
  const geo::PolarSphere sphere({0, 0, 0}, 6371e3);
  int anticlockwise = 0;
  for (std::size_t f = 0; f < 32; ++f) {
    Vec3 p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = sphere.from_lonlat(
          {lon[static_cast<std::size_t>(faces[3 * f + k])], lat[static_cast<std::size_t>(faces[3 * f + k])]});
    anticlockwise += dot(cross(p[1] - p[0], p[2] - p[0]), p[0]) > 0;
  }
  CHECK(anticlockwise == 32);

  const std::vector<int> kind = nc.ints("mesh2d_edge_type", 16), group = nc.ints("mesh2d_edge_physical", 16);
  int open = 0, mainland = 0, coast = 0;
  for (int k : kind) open += k == 3, mainland += k == 1;
  for (int g : group) coast += g == 5;
  CHECK(open == 4);
  CHECK(mainland == 12);
  CHECK(coast == 16);
  CHECK(nc.text("mesh2d_edge_physical", "flag_meanings") == "coast");
}

TEST_CASE("UGRID: a quadrangle beside a clockwise triangle on a plane") {
  MeshModel m;
  m.xyz = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  EntityMesh quad;
  quad.dim = 2, quad.tag = 1, quad.type = ElementType::Quad4;
  quad.nodes = {0, 1, 2, 3};
  quad.connectivity = {0, 1, 2, 3};
  EntityMesh tri;
  tri.dim = 2, tri.tag = 2, tri.type = ElementType::Triangle3;
  tri.nodes = {4};
  tri.connectivity = {1, 2, 4};   // clockwise in x y
  m.entities = {quad, tri};
  OceanGridOptions opt;
  opt.lonlat = false;
  std::string error;
  std::string bytes = ugrid_to_bytes(m, opt, &error);
  REQUIRE_MESSAGE(!bytes.empty(), error);
  UgridRead nc(bytes);
  REQUIRE(nc.dim("mesh2d_nFaces") == 2);
  REQUIRE(nc.dim("mesh2d_nMax_face_nodes") == 4);
  CHECK(nc.dim("mesh2d_nEdges") == 0);   // no curves: no boundary edges
  CHECK(!nc.has("mesh2d_node_cartesian_x"));
  CHECK(nc.ints("mesh2d_face_nodes", 8) == std::vector<int>{0, 1, 2, 3, 1, 4, 2, -1});
  CHECK(nc.text("mesh2d_node_x", "standard_name") == "projection_x_coordinate");
}

TEST_CASE("UGRID: refused without a 2D mesh; a failed save leaves the old file") {
  MeshModel empty;
  OceanGridOptions opt;
  std::string error;
  CHECK(ugrid_to_bytes(empty, opt, &error).empty());
  CHECK(error.find("no 2D mesh") != std::string::npos);

  const sm::testing::ScratchDir dir;
  const std::string path = (dir.path / "old.nc").string();
  { std::ofstream(path) << "old"; }
  CHECK(!save_ugrid(empty, opt, {}, nullptr, path, &error));
  CHECK(sm::testing::read_all(path) == "old");
  MeshModel sq = sm::io::testing::grid_square(2);
  opt.lonlat = false;
  REQUIRE(save_ugrid(sq, opt, {}, nullptr, path, &error));
  CHECK(sm::testing::read_all(path).substr(0, 3) == "CDF");
}
