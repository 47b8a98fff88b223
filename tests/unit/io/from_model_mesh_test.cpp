// io/from_model_mesh: classification of a 1D model mesh (points, curve interiors with t),
// physical groups, and the MSH files compared with what Gmsh 4.8.4 writes for the same
// script (gmsh b.geo -1: the counts and the block headers below come from its output).
#include "io/from_model_mesh.h"

#include <doctest/doctest.h>

#include <string>

#include "io/msh_writer.h"
#include "mesh/mesh1d.h"

using namespace sm;

namespace {

// Point(1..5) lc 0.1 on the unit square and its centre; BSpline(1) = {1,2,3,4,1};
// Line(2) = {1,5}; Physical Curve("c") = {-2}; Physical Point(7) = {5};
geo::Model square_model(bool physicals) {
  geo::Model m;
  const Vec3 p[5] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  for (int i = 0; i < 5; ++i) REQUIRE(m.add_point(i + 1, p[i], 0.1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::BSpline, {1, 2, 3, 4, 1}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {1, 5}).ok());
  if (physicals) {
    REQUIRE(m.add_physical(1, std::nullopt, "c", {-2}).ok());
    REQUIRE(m.add_physical(0, 7, "", {5}).ok());
  }
  return m;
}

std::size_t count_type(const io::MeshModel& mm, int dim) {
  std::size_t n = 0;
  for (const io::EntityMesh& e : mm.entities)
    if (e.dim == dim) n += e.connectivity.size() / io::nodes_per_element(e.type);
  return n;
}

}  // namespace

TEST_CASE("from_model_mesh: entities, classification and parameters") {
  const geo::Model m = square_model(false);
  const Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  const io::MeshModel mm = io::from_model_mesh(m, r.mesh);
  CHECK(io::validate_mesh_model(mm).empty());
  // Gmsh 4.8.4: 41 nodes, 5 point elements, 30 + 8 line elements.
  CHECK(mm.xyz.size() == 41);
  CHECK(count_type(mm, 0) == 5);
  CHECK(count_type(mm, 1) == 38);
  for (const io::EntityMesh& e : mm.entities) {
    if (e.dim != 1) continue;
    CHECK(e.params.size() == e.nodes.size());
    CHECK(e.boundary.size() == 2);
    if (e.tag == 1) CHECK(e.boundary == std::vector<int>{1, -1});
    if (e.tag == 2) CHECK(e.boundary == std::vector<int>{1, -5});
    // Elements chain from the begin point's node to the end point's node.
    CHECK(e.connectivity.front() == r.mesh.vertex_node.at(1));
    for (std::size_t k = 1; k + 1 < e.connectivity.size(); k += 2) CHECK(e.connectivity[k] == e.connectivity[k + 1]);
  }
}

TEST_CASE("from_model_mesh: physical groups select what MSH 4.1 and 2.2 write, as Gmsh") {
  const geo::Model m = square_model(true);
  const Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  const io::MeshModel mm = io::from_model_mesh(m, r.mesh);
  REQUIRE(mm.physicals.size() == 2);
  io::MshOptions o;
  const std::string v41 = io::msh_to_string(mm, o);
  CHECK(v41.find("$PhysicalNames\n1\n1 1 \"c\"\n$EndPhysicalNames") != std::string::npos);
  CHECK(v41.find("$Entities\n5 2 0 0\n") != std::string::npos);
  CHECK(v41.find("$Nodes\n3 9 1 9\n") != std::string::npos);
  CHECK(v41.find("$Elements\n2 9 1 9\n") != std::string::npos);
  CHECK(v41.find("0.5 0.5 0 1 7 \n") != std::string::npos);
  o.version = 22;
  const std::string v22 = io::msh_to_string(mm, o);
  CHECK(v22.find("$Nodes\n9\n") != std::string::npos);
  CHECK(v22.find("$Elements\n9\n1 15 2 7 5 2\n") != std::string::npos);
}

TEST_CASE("from_model_mesh: the same script meshes to the same bytes") {
  const geo::Model m = square_model(true);
  io::MshOptions o;
  o.save_parametric = true;
  const Mesh1dResult a = mesh_curves(m, {}), b = mesh_curves(m, {});
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  const std::string sa = io::msh_to_string(io::from_model_mesh(m, a.mesh), o);
  CHECK(sa == io::msh_to_string(io::from_model_mesh(m, b.mesh), o));
  CHECK(sa.size() > 200);
}
