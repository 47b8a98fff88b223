// Boundary layers in the 1D and 2D meshers (mesh1d.cpp, face_layer.cpp): the layer
// heights on the line leaving a layer's end point and above the wall, the element
// counts, a conforming mesh of quadrangles and triangles, determinism.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "exact/predicates.h"
#include "field/boundary_layer.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"

using namespace sm;

namespace {

// The rectangle (0,0)-(1,0.5) at size 0.1: points 1-4, lines 1-4 (1 the bottom), one face.
geo::Model bl_rectangle() {
  geo::Model m;
  const Vec3 c[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {0, 0.5, 0}};
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_point(i + 1, c[i], 0.1).ok());
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 1, (i + 1) % 4 + 1}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  return m;
}

// The field of the test: layers on the bottom, ending at its two points, 0.01 growing by
// 1.3 below 0.05 (3 layers: 0.01, 0.023, 0.0399).
field::BoundaryLayerParams bl_bottom(bool quads) {
  field::BoundaryLayerParams p;
  p.curves = {1};
  p.end_points = {1, 2};
  p.size = 0.01;
  p.ratio = 1.3;
  p.thickness = 0.05;
  p.size_far = 0.1;
  p.quads = quads;
  return p;
}

ModelMesh bl_mesh(const geo::Model& m, const std::vector<field::BoundaryLayerParams>* layers) {
  Mesh1dOptions o1;
  o1.boundary_layers = layers;
  Mesh1dResult r1 = mesh_curves(m, o1);
  REQUIRE(r1.ok());
  Mesh2dOptions o2;
  o2.boundary_layers = layers;
  const Mesh2dResult r2 = mesh_surfaces(m, r1.mesh, o2);
  INFO(static_cast<int>(r2.error.problem));
  REQUIRE(r2.ok());
  return std::move(r1.mesh);
}

// Every element counter-clockwise in the plane z = 0 (each corner's turn, exactly), every
// directed edge once, and the edges seen once are the boundary curves' edges.
void bl_check_conforming(const ModelMesh& mesh) {
  const SurfaceMesh& sf = mesh.surfaces.at(1);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  auto xy = [&](std::uint32_t v) { return Vec2{mesh.nodes[v].xyz.x, mesh.nodes[v].xyz.y}; };
  auto element = [&](const std::uint32_t* v, int n) {
    for (int i = 0; i < n; ++i) {
      CHECK(orient2d(xy(v[i]), xy(v[(i + 1) % n]), xy(v[(i + 2) % n])) == Sign::Positive);
      CHECK(++directed[{v[i], v[(i + 1) % n]}] == 1);
    }
  };
  for (const auto& t : sf.triangles) element(t.data(), 3);
  for (const auto& q : sf.quads) element(q.data(), 4);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> once, curves;
  for (const auto& [e, n] : directed)
    if (!directed.count({e.second, e.first})) once.push_back(std::minmax(e.first, e.second));
  for (const auto& [tag, cm] : mesh.curves)
    for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) curves.push_back(std::minmax(cm.nodes[k], cm.nodes[k + 1]));
  std::sort(once.begin(), once.end());
  std::sort(curves.begin(), curves.end());
  CHECK(once == curves);
}

}  // namespace

TEST_CASE("boundary layers: heights, counts and a conforming mesh") {
  const geo::Model m = bl_rectangle();
  const std::vector<field::BoundaryLayerParams> quads{bl_bottom(true)};
  const ModelMesh mesh = bl_mesh(m, &quads);
  // The right side leaves point 2 (1, 0): its first nodes at the layer heights, then
  // the rest at about 0.1 (Gmsh 4.8.4: 9 nodes, 0.01, 0.023, 0.0399, 0.1319, ...).
  const CurveMesh& side = mesh.curves.at(2);
  REQUIRE(side.nodes.size() == 9);
  const double heights[3] = {0.01, 0.023, 0.0399};
  for (int i = 0; i < 3; ++i)
    CHECK(mesh.nodes[side.nodes[static_cast<std::size_t>(i) + 1]].xyz.y == doctest::Approx(heights[i]));
  CHECK(mesh.nodes[side.nodes[4]].xyz.y == doctest::Approx(0.1319).epsilon(1e-3));
  // The bottom keeps its 11 nodes; above each, the three layer points.
  const CurveMesh& bottom = mesh.curves.at(1);
  REQUIRE(bottom.nodes.size() == 11);
  const SurfaceMesh& sf = mesh.surfaces.at(1);
  for (std::size_t k = 1; k + 1 < bottom.nodes.size(); ++k) {
    const double x = mesh.nodes[bottom.nodes[k]].xyz.x;
    for (double h : heights) {
      const bool found = std::any_of(sf.interior_nodes.begin(), sf.interior_nodes.end(), [&](std::uint32_t v) {
        return std::abs(mesh.nodes[v].xyz.x - x) < 1e-12 && std::abs(mesh.nodes[v].xyz.y - h) < 1e-12;
      });
      CHECK(found);
    }
  }
  // 10 columns of 3 quadrangles (Gmsh: 30, and 128 triangles besides).
  CHECK(sf.quads.size() == 30);
  CHECK(std::abs(static_cast<double>(sf.triangles.size()) - 128) <= 0.15 * 128);
  bl_check_conforming(mesh);
  // The same bytes again.
  const ModelMesh again = bl_mesh(m, &quads);
  REQUIRE(again.nodes.size() == mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) CHECK(again.nodes[i].xyz == mesh.nodes[i].xyz);
  CHECK(again.surfaces.at(1).quads == sf.quads);
  CHECK(again.surfaces.at(1).triangles == sf.triangles);

  // Quads = 0: each quadrangle two triangles, nothing else changed.
  const std::vector<field::BoundaryLayerParams> tris{bl_bottom(false)};
  const ModelMesh split = bl_mesh(m, &tris);
  CHECK(split.surfaces.at(1).quads.empty());
  CHECK(split.surfaces.at(1).triangles.size() == sf.triangles.size() + 60);
  bl_check_conforming(split);

  // The face excluded: no layer elements (the side keeps its layer points: 1D does not
  // know faces, as in Gmsh).
  std::vector<field::BoundaryLayerParams> excluded{bl_bottom(true)};
  excluded[0].excluded_surfaces = {1};
  const ModelMesh none = bl_mesh(m, &excluded);
  CHECK(none.surfaces.at(1).quads.empty());
  bl_check_conforming(none);
}
