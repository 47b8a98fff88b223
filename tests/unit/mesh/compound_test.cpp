// mesh/compound_curve and mesh/compound_surface: `Compound Curve{...}` chains and the
// concatenation's nodes shared out among its curves; `Compound Surface{...}` as the union
// of plane surfaces meshed once, its elements put back on the originals.
#include "mesh/compound_curve.h"
#include "mesh/compound_surface.h"

#include <doctest/doctest.h>

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"

using namespace sm;

namespace {

// Points 1..n on the x axis at xs, size lc.
void add_axis_points(geo::Model& m, const std::vector<double>& xs, double lc) {
  for (std::size_t i = 0; i < xs.size(); ++i) REQUIRE(m.add_point(static_cast<int>(i) + 1, {xs[i], 0, 0}, lc).ok());
}

// Two unit squares side by side, [0,1]x[0,1] (surface 1) and [1,2]x[0,1] (surface 2),
// sharing line 2 (from (1,0) to (1,1)); z of the right square's far side as given.
void add_two_squares(geo::Model& m, double lc, double z_far = 0) {
  REQUIRE(m.add_point(1, {0, 0, 0}, lc).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, lc).ok());
  REQUIRE(m.add_point(3, {1, 1, 0}, lc).ok());
  REQUIRE(m.add_point(4, {0, 1, 0}, lc).ok());
  REQUIRE(m.add_point(5, {2, 0, z_far}, lc).ok());
  REQUIRE(m.add_point(6, {2, 1, z_far}, lc).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {2, 3}).ok());
  REQUIRE(m.add_curve(3, geo::CurveKind::Line, {3, 4}).ok());
  REQUIRE(m.add_curve(4, geo::CurveKind::Line, {4, 1}).ok());
  REQUIRE(m.add_curve(5, geo::CurveKind::Line, {2, 5}).ok());
  REQUIRE(m.add_curve(6, geo::CurveKind::Line, {5, 6}).ok());
  REQUIRE(m.add_curve(7, geo::CurveKind::Line, {6, 3}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_curve_loop(2, {5, 6, 7, -2}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  REQUIRE(m.add_plane_surface(2, {2}).ok());
}

}  // namespace

TEST_CASE("compound: chains follow the curves end to end, in either direction") {
  geo::Model m;
  add_axis_points(m, {0, 1, 2, 3}, 1);
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {3, 2}).ok());   // runs against the chain
  REQUIRE(m.add_curve(3, geo::CurveKind::Line, {3, 4}).ok());
  const std::vector<CompoundLink> c = chain_compound(m, {2, 1, 3});
  REQUIRE(c.size() == 3);
  // From the free end of the first curve listed that has one: point 1, via 1, -2, 3.
  CHECK(c[0].curve == 1);
  CHECK(!c[0].reversed);
  CHECK(c[1].curve == 2);
  CHECK(c[1].reversed);
  CHECK(c[2].curve == 3);
  CHECK(!c[2].reversed);
  CHECK(chain_compound(m, {1, 3}).empty());        // a gap at points 2-3
  CHECK(chain_compound(m, {1, 1}).empty());        // a curve twice
  CHECK(chain_compound(m, {1, 99}).empty());       // a missing curve
  REQUIRE(m.add_point(5, {1, 1, 0}, 1).ok());
  REQUIRE(m.add_curve(4, geo::CurveKind::Line, {2, 5}).ok());
  CHECK(chain_compound(m, {1, 2, 4}).empty());     // three curves at point 2
}

TEST_CASE("compound: the concatenation's nodes, the one nearest each inner end moved onto it") {
  // Integrals 1.5 + 1.5 + 1.5 = 4.5: Gmsh's count floor(4.5 + 1.99) = 6 nodes at steps of
  // 0.9 (0.9, 1.8, 2.7, 3.6 inside); 1.8 moves to the end point at 1.5, 2.7 to 3.0.
  const std::vector<std::vector<double>> p = compound_node_positions({1.5, 1.5, 1.5});
  REQUIRE(p.size() == 3);
  REQUIRE(p[0].size() == 1);
  CHECK(p[0][0] == doctest::Approx(0.9));
  CHECK(p[1].empty());
  REQUIRE(p[2].size() == 1);
  CHECK(p[2][0] == doctest::Approx(0.6));
  // An inner end nearer the chain's end than any inner node keeps its own node as well.
  const std::vector<std::vector<double>> q = compound_node_positions({0.3, 9.7});
  CHECK(q[0].empty());
  CHECK(q[1].size() == 9);   // 11 nodes: 1, 2, ..., 9 inside, all on the second curve
  CHECK(q[1][0] == doctest::Approx(0.7));
  // Nothing to share: no interior node.
  CHECK(compound_node_positions({0, 0}) == std::vector<std::vector<double>>(2));
}

TEST_CASE("compound: mesh_curves meshes a Compound Curve as one curve") {
  geo::Model m;
  add_axis_points(m, {0, 1.5, 3.0, 4.5}, 1);
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {2, 3}).ok());
  REQUIRE(m.add_curve(3, geo::CurveKind::Line, {4, 3}).ok());   // reversed in the chain
  // Each alone: floor(1.5 + 1.99) = 3 nodes, 2 edges, 6 edges in all.
  const Mesh1dResult alone = mesh_curves(m, {});
  REQUIRE(alone.ok());
  CHECK(alone.mesh.num_curve_edges() == 6);
  MeshConstraints cons;
  cons.compound_curves.push_back({1, 2, 3});
  Mesh1dOptions o;
  o.constraints = &cons;
  const Mesh1dResult r = mesh_curves(m, o);
  REQUIRE(r.ok());
  CHECK(r.mesh.num_curve_edges() == 5);   // Gmsh's 6 nodes for the whole
  const CurveMesh& c1 = r.mesh.curves.at(1);
  REQUIRE(c1.nodes.size() == 3);
  CHECK(r.mesh.nodes[c1.nodes[1]].xyz.x == doctest::Approx(0.9));
  CHECK(r.mesh.curves.at(2).nodes.size() == 2);
  const CurveMesh& c3 = r.mesh.curves.at(3);
  REQUIRE(c3.nodes.size() == 3);
  CHECK(c3.t[1] == doctest::Approx(0.6));   // x = 3.6 on the curve from 4.5 to 3.0
  CHECK(r.mesh.nodes[c3.nodes[1]].xyz.x == doctest::Approx(3.6));
  // A transfinite member keeps its count: the group is meshed curve by curve.
  cons.curves[2] = TransfiniteCurveSpec{5};
  const Mesh1dResult t = mesh_curves(m, o);
  REQUIRE(t.ok());
  CHECK(t.mesh.curves.at(2).nodes.size() == 5);
  CHECK(t.mesh.curves.at(1).nodes.size() == 3);
}

TEST_CASE("compound: two squares meshed as one, the triangles back on each square") {
  geo::Model m;
  add_two_squares(m, 0.2);
  const CompoundSurfacePlan plan = plan_compound_surfaces(m, {{1, 2}});
  REQUIRE(plan.declined.empty());
  REQUIRE(plan.groups.size() == 1);
  const int u = plan.groups[0].union_tag;
  CHECK(plan.model.surface(1) == nullptr);
  CHECK(plan.model.surface(2) == nullptr);
  REQUIRE(plan.model.surface(u) != nullptr);
  CHECK(plan.model.surface(u)->loops.size() == 1);
  Mesh1dResult r1 = mesh_curves(plan.model, {});
  REQUIRE(r1.ok());
  ModelMesh mesh = std::move(r1.mesh);
  const Mesh2dResult r2 = mesh_surfaces(plan.model, mesh, {});
  REQUIRE(r2.ok());
  const std::size_t total = mesh.surfaces.at(u).triangles.size();
  classify_compound_elements(m, plan, mesh);
  CHECK(mesh.surfaces.count(u) == 0);
  const SurfaceMesh& s1 = mesh.surfaces.at(1);
  const SurfaceMesh& s2 = mesh.surfaces.at(2);
  CHECK(!s1.triangles.empty());
  CHECK(!s2.triangles.empty());
  CHECK(s1.triangles.size() + s2.triangles.size() == total);
  // Each triangle on the square holding its centroid (one on the shared line: the first).
  for (const auto& t : s1.triangles)
    CHECK((mesh.nodes[t[0]].xyz.x + mesh.nodes[t[1]].xyz.x + mesh.nodes[t[2]].xyz.x) / 3 <= 1 + 1e-12);
  for (const auto& t : s2.triangles)
    CHECK((mesh.nodes[t[0]].xyz.x + mesh.nodes[t[1]].xyz.x + mesh.nodes[t[2]].xyz.x) / 3 > 1 + 1e-12);
  // The shared line constrains nothing: its interior nodes are in no triangle.
  std::set<std::uint32_t> used;
  for (const SurfaceMesh* s : {&s1, &s2})
    for (const auto& t : s->triangles) used.insert(t.begin(), t.end());
  const CurveMesh& shared = mesh.curves.at(2);
  REQUIRE(shared.nodes.size() > 2);
  for (std::size_t i = 1; i + 1 < shared.nodes.size(); ++i) CHECK(used.count(shared.nodes[i]) == 0);
}

TEST_CASE("compound: surfaces not in one plane are meshed one by one") {
  geo::Model m;
  add_two_squares(m, 0.5, 0.5);   // the right square is tilted
  const CompoundSurfacePlan plan = plan_compound_surfaces(m, {{1, 2}});
  CHECK(plan.groups.empty());
  REQUIRE(plan.declined.size() == 1);
  CHECK(plan.declined[0].surfaces == std::vector<int>{1, 2});
  CHECK(plan.declined[0].why.find("not in one plane") != std::string::npos);
  CHECK(plan.model.surface(1) != nullptr);
  CHECK(plan.model.surface(2) != nullptr);
  // A single surface, or a missing one, is no compound at all.
  geo::Model flat;
  add_two_squares(flat, 0.5);
  const CompoundSurfacePlan one = plan_compound_surfaces(flat, {{1, 99}});
  CHECK(one.groups.empty());
  CHECK(one.declined.empty());
}

TEST_CASE("compound: the mesher's words about a union name the script's surfaces") {
  geo::Model m;
  add_two_squares(m, 0.5);
  const CompoundSurfacePlan plan = plan_compound_surfaces(m, {{1, 2}});
  REQUIRE(plan.groups.size() == 1);
  const int u = plan.groups[0].union_tag;
  MeshError e;
  e.kind = MeshErrorKind::Failed;
  e.surface = u;
  e.add_entity(2, u);
  name_compound_unions(plan, e);
  CHECK(e.tag(0) == 1);
  CHECK(e.surface == u);   // worded as meshed: the text overload names the union
  std::string text = fmt::format("surface {}: no progress; surface {}0 untouched", u, u);
  name_compound_unions(plan, text);
  CHECK(text == fmt::format("the union of Compound Surface{{1, 2}}: no progress; surface {}0 untouched", u));
}
