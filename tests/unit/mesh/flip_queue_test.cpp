// FlipQueue: an edge is queued once (by its smaller side) unless it is on the hull or
// constrained; after a flip, the quad's four outer edges are queued.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "mesh/modify/flip_queue.h"

using namespace sm;

namespace {

// The quad 0 1 2 3 cut along 0-2, with a triangle outside each of its four sides (so that
// they are interior edges), all counter-clockwise.
bool quad_with_neighbours(TriangleStore& m) {
  return build_triangulation({{0, 0}, {2, -1}, {4, 0}, {2, 1}, {1, -2}, {3, -2}, {3, 2}, {1, 2}},
                             {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}, {1, 5, 2}, {2, 6, 3}, {3, 7, 0}}, m);
}

std::pair<std::uint32_t, std::uint32_t> edge_of(const TriangleStore& m, Side s) {
  const std::uint32_t a = m.org(s).value, b = m.dest(s).value;
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

TEST_CASE("flip queue: an edge once, by its smaller side; not the hull, not a constrained edge") {
  TriangleStore m;
  REQUIRE(quad_with_neighbours(m));
  FlipQueue q(m.corner.size());
  const Side d = m.side_between(VertexId{0}, VertexId{2});
  const Side dt = m.twin[d.value];
  REQUIRE(dt.valid());
  q.push_edge(m, d);
  q.push_edge(m, dt);   // the same edge, from the other side
  REQUIRE(q.stack.size() == 1);
  CHECK(q.stack[0].value == std::min(d.value, dt.value));
  q.push_edge(m, m.side_between(VertexId{0}, VertexId{4}));   // on the hull
  const Side c = m.side_between(VertexId{1}, VertexId{2});
  m.set_edge_flags(c, kConstrained);
  q.push_edge(m, c);
  CHECK(q.stack.size() == 1);
  CHECK(q.pop() == Side{std::min(d.value, dt.value)});
  CHECK(q.empty());
  q.push_edge(m, dt);   // popped: it may be queued again
  CHECK(q.stack.size() == 1);
}

TEST_CASE("flip queue: after a flip, the four outer edges of the quad, each once") {
  TriangleStore m;
  REQUIRE(quad_with_neighbours(m));
  FlipQueue q(m.corner.size());
  const Side n = m.flip(m.side_between(VertexId{0}, VertexId{2}));
  q.push_outer_edges(m, n);
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (Side s : q.stack) edges.insert(edge_of(m, s));
  CHECK(q.stack.size() == 4);
  CHECK(edges == std::set<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}, {1, 2}, {2, 3}, {0, 3}});
  q.push_outer_edges(m, n);   // already queued
  CHECK(q.stack.size() == 4);
  // A constrained outer edge is left out.
  TriangleStore r;
  REQUIRE(quad_with_neighbours(r));
  r.set_edge_flags(r.side_between(VertexId{2}, VertexId{3}), kConstrained);
  FlipQueue p(r.corner.size());
  p.push_outer_edges(r, r.flip(r.side_between(VertexId{0}, VertexId{2})));
  CHECK(p.stack.size() == 3);
}
