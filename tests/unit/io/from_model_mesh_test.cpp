// io/from_model_mesh: classification of a 1D model mesh (points, curve interiors with t),
// physical groups, and the MSH files compared with what Gmsh 4.8.4 writes for the same
// script (gmsh b.geo -1: the counts and the block headers below come from its output).
#include "io/from_model_mesh.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <fmt/format.h>

#include "geo/sphere.h"
#include "io/msh_writer.h"
#include "io/vtk_writer.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"

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

TEST_CASE("from_model_mesh: without parametric coordinates, the same mesh and the same file") {
  const geo::Model m = square_model(false);
  const Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  const io::MeshModel with = io::from_model_mesh(m, r.mesh);
  const io::MeshModel without = io::from_model_mesh(m, r.mesh, nullptr, /*parametric=*/false);
  CHECK(without.xyz == with.xyz);
  REQUIRE(without.entities.size() == with.entities.size());
  std::size_t params = 0;
  for (std::size_t i = 0; i < with.entities.size(); ++i) {
    CHECK(without.entities[i].nodes == with.entities[i].nodes);
    CHECK(without.entities[i].connectivity == with.entities[i].connectivity);
    CHECK(without.entities[i].params.empty());
    params += with.entities[i].params.size();
  }
  CHECK(params > 0);
  // MSH without Mesh.SaveParametric writes no parametric coordinates: the same bytes.
  const io::MshOptions o;
  CHECK(io::msh_to_string(without, o) == io::msh_to_string(with, o));
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

namespace {

// The unit square (lc 0.1) with two closed B-spline islands far below the size (each gets 2
// mesh edges: mesh2d leaves their hole loops out with a warning) and one construction
// point, a free Point(20) at the centre; the surface and every curve in physical groups.
struct Islands {
  geo::Model model;
  ModelMesh mesh;
  std::vector<int> island_curves, island_points;
};

Islands square_with_islands() {
  Islands s;
  geo::Model& m = s.model;
  const Vec3 c[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_point(i + 1, c[i], 0.1).ok());
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 1, (i + 1) % 4 + 1}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  std::vector<int> loops{1}, coast{1, 2, 3, 4};
  const double centres[2][2] = {{0.3, 0.3}, {0.7, 0.6}};
  for (int k = 0; k < 2; ++k) {
    const int p = 5 + 4 * k;
    for (int i = 0; i < 4; ++i) {
      const double a = geo::kPi / 2 * i;
      REQUIRE(
          m.add_point(p + i, {centres[k][0] + 0.005 * std::cos(a), centres[k][1] + 0.005 * std::sin(a), 0}, 0.1).ok());
      s.island_points.push_back(p + i);
    }
    REQUIRE(m.add_curve(5 + k, geo::CurveKind::BSpline, {p, p + 1, p + 2, p + 3, p}).ok());
    REQUIRE(m.add_curve_loop(2 + k, {5 + k}).ok());
    loops.push_back(2 + k);
    coast.push_back(5 + k);
    s.island_curves.push_back(5 + k);
  }
  REQUIRE(m.add_point(20, {0.5, 0.5, 0}, 0.1).ok());
  REQUIRE(m.add_plane_surface(1, loops).ok());
  REQUIRE(m.add_physical(2, std::nullopt, "sea", {1}).ok());
  REQUIRE(m.add_physical(1, std::nullopt, "coast", coast).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  s.mesh = std::move(r1.mesh);
  const Mesh2dResult r2 = mesh_surfaces(m, s.mesh, {});
  REQUIRE(r2.ok());
  REQUIRE(r2.notes.size() == 1);
  CHECK(r2.notes.front().kind == MeshNoteKind::IslandsLeftOut);
  CHECK(r2.notes.front().loops.size() == 2);
  return s;
}

}  // namespace

TEST_CASE("from_model_mesh: the islands mesh2d left out, and construction points, are not in the mesh") {
  const Islands s = square_with_islands();
  std::vector<std::uint32_t> index;
  const io::MeshModel mm = io::from_model_mesh(s.model, s.mesh, &index);
  REQUIRE(io::validate_mesh_model(mm).empty());
  REQUIRE(index.size() == s.mesh.nodes.size());
  // The mesh as meshed: its triangles' nodes, each once.
  std::set<std::uint32_t> in_triangles;
  for (const auto& t : s.mesh.surfaces.at(1).triangles) in_triangles.insert(t.begin(), t.end());
  CHECK(mm.xyz.size() == in_triangles.size());
  CHECK(s.mesh.nodes.size() == in_triangles.size() + 2 * 2 + 6 + 1);   // 2 per island, 6 control points, Point(20)
  // Every node left is a triangle's, and what went is named by the index.
  std::vector<char> used(mm.xyz.size(), 0);
  for (const io::EntityMesh& e : mm.entities) {
    if (e.dim == 2)
      for (std::uint32_t v : e.connectivity) used[v] = 1;
    CHECK_FALSE((e.dim == 1 && std::count(s.island_curves.begin(), s.island_curves.end(), e.tag)));
    CHECK_FALSE((e.dim == 0 && std::count(s.island_points.begin(), s.island_points.end(), e.tag)));
    CHECK_FALSE((e.dim == 0 && e.tag == 20));
  }
  CHECK(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
  for (std::uint32_t v = 0; v < s.mesh.nodes.size(); ++v) {
    CAPTURE(v);
    CHECK((index[v] != 0xFFFFFFFFu) == (in_triangles.count(v) != 0));
    if (index[v] != 0xFFFFFFFFu) CHECK(mm.xyz[index[v]] == s.mesh.nodes[v].xyz);
  }
  // The one node order: entity order, each entity's nodes in turn, from 0.
  std::uint32_t next = 0;
  for (std::size_t i : io::entity_order(mm))
    for (std::uint32_t v : mm.entities[i].nodes) CHECK(v == next++);
  CHECK(next == mm.xyz.size());
  // Every file holds those nodes: MSH 4.1 and 2.2 (tags 1..N in that order), VTK, UGRID.
  io::MshOptions o;
  const std::string v41 = io::msh_to_string(mm, o);
  CHECK(v41.find(fmt::format(" {} 1 {}\n", mm.xyz.size(), mm.xyz.size())) != std::string::npos);
  o.version = 22;
  CHECK(io::msh_to_string(mm, o).find(fmt::format("$Nodes\n{}\n", mm.xyz.size())) != std::string::npos);
  CHECK(io::vtk_to_string(mm, {}).find(fmt::format("POINTS {} double", mm.xyz.size())) != std::string::npos);
}

TEST_CASE("from_model_mesh: without a 2D mesh every point and curve stays (Gmsh's 1D files)") {
  const Islands s = square_with_islands();
  const Mesh1dResult r = mesh_curves(s.model, {});
  REQUIRE(r.ok());
  const io::MeshModel mm = io::from_model_mesh(s.model, r.mesh);
  CHECK(mm.xyz.size() == r.mesh.nodes.size());
  std::size_t curves = 0;
  for (const io::EntityMesh& e : mm.entities) curves += e.dim == 1;
  CHECK(curves == 6);
}

namespace {

// The unit square (lc 0.5) and a free Point(9) at (2, 2): a circle's centre would be one.
geo::Model square_and_free_point() {
  geo::Model m;
  const Vec3 c[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_point(i + 1, c[i], 0.5).ok());
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 1, (i + 1) % 4 + 1}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  REQUIRE(m.add_point(9, {2, 2, 0}, 0.5).ok());
  return m;
}

bool has_point(const io::MeshModel& mm, int tag) {
  return std::any_of(mm.entities.begin(), mm.entities.end(),
                     [tag](const io::EntityMesh& e) { return e.dim == 0 && e.tag == tag; });
}

io::MeshModel mesh_of(const geo::Model& m) {
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  REQUIRE(mesh_surfaces(m, r1.mesh, {}).ok());
  return io::from_model_mesh(m, r1.mesh);
}

}  // namespace

TEST_CASE("from_model_mesh: a flat model without groups keeps its free points, as Gmsh writes every point") {
  geo::Model m = square_and_free_point();
  io::MeshModel mm = mesh_of(m);
  CHECK(has_point(mm, 9));
  CHECK(std::count(mm.xyz.begin(), mm.xyz.end(), Vec3{2, 2, 0}) == 1);
  // With a physical group only the groups' entities are written (Gmsh's Mesh.SaveAll 0).
  REQUIRE(m.add_physical(2, std::nullopt, "sea", {1}).ok());
  mm = mesh_of(m);
  CHECK_FALSE(has_point(mm, 9));
  CHECK(std::count(mm.xyz.begin(), mm.xyz.end(), Vec3{2, 2, 0}) == 0);
}

TEST_CASE("from_model_mesh: a group keeps a deleted entity's tag; a group with no existing entity is not written") {
  geo::Model m = square_and_free_point();
  REQUIRE(m.add_physical(0, 7, "", {9}).ok());
  REQUIRE(m.add_physical(2, 6, "sea", {1}).ok());
  REQUIRE(m.remove({{2, 1}}, false).ok());
  REQUIRE(m.remove({{0, 9}}, false).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());   // made again: in group 6 again
  const io::MeshModel mm = mesh_of(m);
  REQUIRE(mm.physicals.size() == 1);
  CHECK(mm.physicals.front().tag == 6);
  const auto surface = std::find_if(mm.entities.begin(), mm.entities.end(),
                                    [](const io::EntityMesh& e) { return e.dim == 2 && e.tag == 1; });
  REQUIRE(surface != mm.entities.end());
  CHECK(surface->physical_tags == std::vector<int>{6});
}

TEST_CASE("from_model_mesh: the same model for every thread count, across the copies' chunks") {
  // The unit square at lc 0.004: about 140,000 triangles and 72,000 nodes, so the threaded
  // copies and renumbering (chunks of 65,536 entries) split both the nodes and the
  // triangles' corners between threads.
  geo::Model m = square_and_free_point();
  REQUIRE(m.set_mesh_size({1, 2, 3, 4}, 0.004).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  REQUIRE(mesh_surfaces(m, r1.mesh, {}).ok());
  REQUIRE(r1.mesh.nodes.size() > (std::size_t{1} << 16));
  std::vector<std::uint32_t> index1;
  const io::MeshModel one = io::from_model_mesh(m, r1.mesh, &index1, true, 1);
  CHECK(io::validate_mesh_model(one).empty());
  for (int threads : {2, 3}) {
    std::vector<std::uint32_t> index;
    const io::MeshModel many = io::from_model_mesh(m, r1.mesh, &index, true, threads);
    CHECK(index == index1);
    CHECK(many.xyz == one.xyz);
    REQUIRE(many.entities.size() == one.entities.size());
    for (std::size_t i = 0; i < one.entities.size(); ++i) {
      CHECK(many.entities[i].nodes == one.entities[i].nodes);
      CHECK(many.entities[i].connectivity == one.entities[i].connectivity);
      CHECK(many.entities[i].params == one.entities[i].params);
    }
  }
}
