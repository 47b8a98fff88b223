// Mesh.MinTimeStep after meshing (mesh/time_step_repair.h): the coast node behind a sliver
// is collapsed onto its neighbour along the coast, which raises the mesh's step; model
// vertices stay where they are.
#include "mesh/time_step_repair.h"

#include <cmath>

#include <doctest/doctest.h>

using namespace sm;

namespace {

// A 1000 m square (plane, uv = xy) whose bottom coast has two nodes 10 m apart at x = 500
// and 510, fanned to one inner node at (500, 400):
//
//   5 ------------- 4
//   |  \         /  |
//   |      6        |       triangle 1-2-6 is the sliver: a 10 m edge, about 1 s
//   |   /  | \   \  |       in 10 m of water; every other one is over 40 s.
//   0 ---- 1-2 ---- 3
ModelMesh rp_coast_mesh() {
  ModelMesh m;
  for (Vec2 p : {Vec2{0, 0}, Vec2{500, 0}, Vec2{510, 0}, Vec2{1000, 0}, Vec2{1000, 1000}, Vec2{0, 1000},
                 Vec2{500, 400}})
    m.add_node({p.x, p.y, 0}, p);
  m.vertex_node = {{1, 0}, {2, 3}, {3, 4}, {4, 5}};
  m.curves[1] = {1, {0, 1, 2, 3}, {0, 0.5, 0.51, 1}, {}};
  m.curves[2] = {2, {3, 4}, {0, 1}, {}};
  m.curves[3] = {3, {4, 5}, {0, 1}, {}};
  m.curves[4] = {4, {5, 0}, {0, 1}, {}};
  m.surfaces[1].tag = 1;
  m.surfaces[1].interior_nodes = {6};
  m.surfaces[1].triangles = {{0, 1, 6}, {1, 2, 6}, {2, 3, 6}, {3, 4, 6}, {4, 5, 6}, {5, 0, 6}};
  m.dim = 2;
  return m;
}

}  // namespace

TEST_CASE("time step repair: the coast node of a sliver is collapsed along the coast and the step rises") {
  ModelMesh m = rp_coast_mesh();
  const std::vector<double> depth(m.nodes.size(), 10.0);
  const double before = courant_time_step(m, depth).dt;
  CHECK(before == doctest::Approx(10 / std::sqrt(9.81 * 10)));
  const StepRepairResult r = repair_short_steps(m, depth, 10.0, {});
  REQUIRE(r.removed.size() == 1);
  CHECK(r.removed[0].edge == doctest::Approx(10));
  CHECK(r.removed[0].step == doctest::Approx(before));
  CHECK(r.removed[0].surface == 1);
  // The sliver is gone, the coast runs 0 -> 2 -> 3 (node 1 moved onto 2) and every
  // triangle left is over 10 s.
  CHECK(m.surfaces[1].triangles.size() == 5);
  CHECK(m.curves[1].nodes == std::vector<std::uint32_t>{0, 2, 3});
  CHECK(m.curves[1].t.size() == 3);
  const TimeStep after = courant_time_step(m, depth);
  CHECK(after.dt >= 10.0);
  CHECK(after.dt == doctest::Approx(400.12498 / std::sqrt(9.81 * 10)).epsilon(1e-6));   // edge 2-6
  for (const auto& t : m.surfaces[1].triangles) {
    CHECK(t[0] != 1);
    CHECK(t[1] != 1);
    CHECK(t[2] != 1);
  }
  // Nothing left to do: a second call changes nothing.
  CHECK(repair_short_steps(m, depth, 10.0, {}).removed.empty());
}

TEST_CASE("time step repair: model vertices are not moved, and no step asked removes nothing") {
  ModelMesh m = rp_coast_mesh();
  const std::vector<double> depth(m.nodes.size(), 10.0);
  CHECK(repair_short_steps(m, depth, 0.0, {}).removed.empty());
  CHECK(m.surfaces[1].triangles.size() == 6);
  // Both ends of the short edge made model vertices: the sliver has to stay.
  m.vertex_node[5] = 1;
  m.vertex_node[6] = 2;
  const StepRepairResult r = repair_short_steps(m, depth, 10.0, {});
  CHECK(r.removed.empty());
  CHECK(m.surfaces[1].triangles.size() == 6);
  CHECK(courant_time_step(m, depth).dt == doctest::Approx(10 / std::sqrt(9.81 * 10)));
}
