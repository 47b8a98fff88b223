// Point insertion into a constrained Delaunay triangulation, checked after
// every single insertion.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh/check.h"
#include "mesh/insert.h"
#include "testing_domains.h"

using namespace sm;

TEST_CASE("insert: one point at a time into a CDT with an internal constraint") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, false);
  const VertexId a = m.add_vertex({0.125, 0.25}), b = m.add_vertex({0.875, 0.75});  // dyadic: midpoint exactly on a-b
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {sq}, &edges));
  REQUIRE(recover_edges(m, PlanarGeometry{&m.xy}, {{a, b}}).clean());
  edges.push_back({a, b});
  PointInserter ins(m);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0, 1);
  TriId hint{0};
  int inserted = 0, blocked = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec2 p{U(rng), U(rng)};
    const InsertOutcome out = ins.insert_near(p, hint);
    if (out == InsertOutcome::Inserted) {
      ++inserted;
      CHECK(m.xy[ins.last_vertex().value] == p);
      REQUIRE(ins.created().size() >= 3);
      hint = TriId{ins.created()[0]};
    } else {
      ++blocked;  // p beyond the constraint a-b as seen from the hint
      CHECK(out == InsertOutcome::Outside);
    }
    INFO(check_topology(m).error);
    REQUIRE(check_topology(m).ok());
    REQUIRE(check_constraints(m, edges).ok());
    REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
  }
  CHECK(inserted > 200);
  CHECK(blocked > 20);
  // Outside the square, a duplicate, and a point on the constraint.
  const std::uint32_t nv = m.num_vertices(), nt = m.num_triangles();
  CHECK(ins.insert_near({1.5, 0.5}, hint) == InsertOutcome::Outside);
  const TriId ta = tri_of(m.out_side[a.value]);
  CHECK(ins.insert(m.xy[a.value], ta) == InsertOutcome::Duplicate);
  const Vec2 mid = 0.5 * (m.xy[a.value] + m.xy[b.value]);  // (0.5, 0.5), exactly on a-b
  const TriId tm = ins.locate(mid, tri_of(m.out_side[a.value]));
  REQUIRE(tm.valid());
  CHECK(ins.insert(mid, tm) == InsertOutcome::NotVisible);
  CHECK(m.num_vertices() == nv);
  CHECK(m.num_triangles() == nt);
  CHECK(check_topology(m).ok());
}

TEST_CASE("insert: a large cavity (the centre of 40 cocircular points), out_side left to the caller") {
  // A ring of 40 points around the centre of a square: inserting the centre
  // empties the whole disc, a cavity far beyond the scanned size, so the
  // visited triangles are marked; the marks must all be gone afterwards.
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, 4.0, false);
  for (int i = 0; i < 40; ++i) m.add_vertex({std::cos(i * M_PI / 20), std::sin(i * M_PI / 20)});
  REQUIRE(testing::boundary_mesh(m, {sq}));
  PointInserter ins(m);
  ins.keep_out_side = false;
  const std::vector<Side> before = m.out_side;
  const TriId t = ins.locate({0.001, 0.0005}, TriId{0});
  REQUIRE(t.valid());
  REQUIRE(ins.insert({0.001, 0.0005}, t) == InsertOutcome::Inserted);
  CHECK(ins.created().size() >= 40);
  for (std::uint32_t s = 0; s < m.num_slots(); ++s) CHECK((m.tri_flags[s] & kMark) == 0);
  CHECK(m.out_side[ins.last_vertex().value] == Side{});  // not maintained
  m.rebuild_out_side();
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  CHECK(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
  // Every ring point is now a neighbour of the centre.
  for (std::uint32_t v = 4; v < 44; ++v) CHECK(m.has_edge(ins.last_vertex(), VertexId{v}));
}

TEST_CASE("insert: a point that is not finite is outside, the mesh unchanged") {
  TriangleStore m;
  const Loop l = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.5, false);
  REQUIRE(testing::boundary_mesh(m, {l}));
  const std::uint32_t nv = m.num_vertices(), nt = m.num_triangles();
  PointInserter ins(m);
  TriId any;
  for (std::uint32_t t = 0; t < m.num_slots() && !any.valid(); ++t)
    if (m.alive(TriId{t})) any = TriId{t};
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (Vec2 p : {Vec2{inf, inf}, Vec2{-inf, 0.5}, Vec2{nan, 0.5}, Vec2{0.5, nan}}) {
    CHECK_FALSE(ins.locate(p, any).valid());
    CHECK(ins.insert_near(p, any) == InsertOutcome::Outside);
    CHECK(ins.insert(p, any) == InsertOutcome::Outside);
  }
  CHECK(m.num_vertices() == nv);
  CHECK(m.num_triangles() == nt);
  CHECK(check_topology(m).ok());
}
