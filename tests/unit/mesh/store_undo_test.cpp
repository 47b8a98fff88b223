// The store's undo journal (mesh/store_undo.h): after flips and moves (the quality pass),
// Delaunay insertions, edge splits, flags and removals, restore() gives back the very arrays
// a copy taken before holds, and does so again after a second batch of changes; so after an
// insertion whose cavity is large enough for the inserter to mark its triangles; a change
// that bypasses the journal is seen by the fingerprint it checks against.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "mesh/insert.h"
#include "mesh/modify/optimize.h"
#include "mesh/modify/split.h"
#include "mesh/refine.h"
#include "mesh/store_undo.h"
#include "testing_domains.h"

using namespace sm;

namespace {

// del2d's square with a hole at size h: many triangles below 0.9 for the quality pass.
TriangleStore su_square(double h, std::uint32_t* fixed) {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  const Loop hole = testing::circle_loop(m, {0.4, 0.6}, 0.15, h, true);
  REQUIRE(testing::boundary_mesh(m, {sq, hole}));
  *fixed = m.num_vertices();
  RefineOptions opt;
  opt.size = h;
  REQUIRE(refine_del2d(m, opt).ok());
  return m;
}

bool su_same(const TriangleStore& a, const TriangleStore& b) {
  return a.xy.size() == b.xy.size() && std::memcmp(a.xy.data(), b.xy.data(), a.xy.size() * sizeof(Vec2)) == 0 &&
         a.out_side == b.out_side && a.corner == b.corner && a.twin == b.twin && a.side_flags == b.side_flags &&
         a.tri_flags == b.tri_flags && a.free_tris == b.free_tris;
}

// Changes of every kind the quality floor makes: the quality pass, insertions, splits of
// interior edges, flags, and removals of triangles (slots then reused by the insertions).
void su_change(TriangleStore& m, std::uint32_t fixed) {
  OptimizeOptions oo;
  oo.threshold = 0.95;
  const OptimizeStats st = optimize_quality(m, fixed, oo);
  CHECK(st.swaps + st.moves > 0);
  std::uint32_t split = 0;
  for (std::uint32_t t = 0; t < m.num_slots() && split < 20; t += 37) {
    if (!m.alive(TriId{t})) continue;
    const Side s = side_of(TriId{t}, 0);
    if (m.constrained(s) || !m.twin[s.value].valid()) continue;
    const Vec2 mid = 0.5 * (m.pos(m.org(s)) + m.pos(m.dest(s)));
    split += split_edge(m, s, mid).valid();
  }
  CHECK(split > 0);
  for (std::uint32_t t = 5; t < m.num_slots(); t += 211)
    if (m.alive(TriId{t})) m.set_edge_flags(side_of(TriId{t}, 1), kBoundary);
  for (std::uint32_t t = 3; t < m.num_slots(); t += 401)
    if (m.alive(TriId{t})) m.kill_triangle(TriId{t});
  PointInserter ins(m);
  std::uint32_t inserted = 0;
  for (std::uint32_t t = 7; t < m.num_slots() && inserted < 30; t += 53) {
    if (!m.alive(TriId{t})) continue;
    const Vec2 c =
        (1.0 / 3) * (m.pos(m.vertex(TriId{t}, 0)) + m.pos(m.vertex(TriId{t}, 1)) + m.pos(m.vertex(TriId{t}, 2)));
    inserted += ins.insert(c, TriId{t}) == InsertOutcome::Inserted;
  }
  CHECK(inserted > 0);
}

}  // namespace

TEST_CASE("StoreUndo: restore gives back the store as it was, twice") {
  std::uint32_t fixed = 0;
  TriangleStore m = su_square(0.03, &fixed);
  const TriangleStore copy = m;
  const std::uint64_t fp = store_fingerprint(m);
  CHECK(fp == store_fingerprint(copy));
  StoreUndo undo(m);
  su_change(m, fixed);
  CHECK_FALSE(su_same(m, copy));
  CHECK(store_fingerprint(m) != fp);
  CHECK(undo.saved_triangles() > 0);
  CHECK(undo.saved_vertices() > 0);
  // Far fewer than the store: the journal holds what changed.
  CHECK(undo.saved_triangles() < m.num_slots());
  undo.restore(m);
  CHECK(su_same(m, copy));
  CHECK(m.undo_link.journal == &undo);
  su_change(m, fixed);
  CHECK_FALSE(su_same(m, copy));
  undo.restore(m);
  CHECK(su_same(m, copy));
}

TEST_CASE("StoreUndo: a copy of a journalled store has no journal; a write past it changes the fingerprint") {
  std::uint32_t fixed = 0;
  TriangleStore m = su_square(0.05, &fixed);
  const std::uint64_t fp = store_fingerprint(m);
  StoreUndo undo(m);
  const TriangleStore copy = m;
  CHECK(copy.undo_link.journal == nullptr);
  // Written without telling the journal (what restore()'s check is there for): nothing
  // saved, and the fingerprint sees it.
  m.xy[fixed].x += 1e-3;
  CHECK(undo.saved_vertices() == 0);
  CHECK(store_fingerprint(m) != fp);
  m.xy[fixed].x -= 1e-3;
}

TEST_CASE("StoreUndo: an insertion into a large cavity (its triangles marked) is undone") {
  // The boundary of a circle alone: every triangle's circumcircle is the circle, so its
  // centre's cavity is every triangle, past the inserter's 16 scanned without marks.
  TriangleStore m;
  const Loop circle = testing::circle_loop(m, {0, 0}, 1, 0.1, false);
  REQUIRE(testing::boundary_mesh(m, {circle}));
  REQUIRE(m.num_triangles() > 20);
  const TriangleStore copy = m;
  StoreUndo undo(m);
  PointInserter ins(m);
  TriId first;
  for (std::uint32_t t = 0; t < m.num_slots() && !first.valid(); ++t)
    if (m.alive(TriId{t})) first = TriId{t};
  const TriId at = ins.locate({0, 0}, first);
  REQUIRE(at.valid());
  REQUIRE(ins.insert({0, 0}, at) == InsertOutcome::Inserted);
  CHECK(ins.created().size() > 16);
  CHECK_FALSE(su_same(m, copy));
  undo.restore(m);
  CHECK(su_same(m, copy));
}
