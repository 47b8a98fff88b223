// The flat store: building, rotation (side_between), flip, kill, compact,
// each followed by the checkers.
#include <doctest/doctest.h>

#include <array>
#include <random>
#include <set>

#include "mesh/check.h"
#include "mesh/delaunay.h"
#include "mesh/triangulation.h"

using namespace sm;

namespace {

// Unit square 0(0,0) 1(1,0) 2(1,1) 3(0,1) split by the diagonal 0-2.
TriangleStore unit_square_02() {
  TriangleStore m;
  REQUIRE(build_triangulation({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}, m));
  return m;
}

// A 3x3 grid of vertices (ids row-major), each cell split along one diagonal.
TriangleStore grid3() {
  std::vector<Vec2> xy;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) xy.push_back({double(i), double(j)});
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t j = 0; j < 2; ++j)
    for (std::uint32_t i = 0; i < 2; ++i) {
      const std::uint32_t a = 3 * j + i, b = a + 1, c = a + 4, d = a + 3;
      tris.push_back({a, b, c});
      tris.push_back({a, c, d});
    }
  TriangleStore m;
  REQUIRE(build_triangulation(xy, tris, m));
  return m;
}

}  // namespace

TEST_CASE("triangulation: build, sides, rotation") {
  TriangleStore m = unit_square_02();
  CHECK(check_topology(m).ok());
  CHECK(m.num_triangles() == 2);
  const Side s = m.side_between(VertexId{0}, VertexId{2});
  REQUIRE(s.valid());
  CHECK(m.org(s) == VertexId{0});
  CHECK(m.dest(s) == VertexId{2});
  CHECK(m.apex(s) == VertexId{3});
  CHECK(m.org(m.twin[s.value]) == VertexId{2});
  CHECK(m.has_edge(VertexId{1}, VertexId{0}));  // only 0->1 exists (hull)
  CHECK_FALSE(m.side_between(VertexId{1}, VertexId{0}).valid());
  CHECK_FALSE(m.has_edge(VertexId{1}, VertexId{3}));
  const PlanarGeometry g{&m.xy};
  CHECK(check_delaunay(m, g).ok());  // cocircular: either diagonal is Delaunay
}

TEST_CASE("triangulation: flip of a convex quad keeps topology and flags") {
  TriangleStore m = unit_square_02();
  const Side hull = m.side_between(VertexId{0}, VertexId{1});
  m.set_edge_flags(hull, kBoundary);
  const Side s = m.side_between(VertexId{0}, VertexId{2});
  const Side n = m.flip(s);
  CHECK(m.org(n) == VertexId{1});  // d -> c
  CHECK(m.dest(n) == VertexId{3});
  CHECK(m.has_edge(VertexId{1}, VertexId{3}));
  CHECK_FALSE(m.has_edge(VertexId{0}, VertexId{2}));
  CHECK(check_topology(m).ok());
  const Side h2 = m.side_between(VertexId{0}, VertexId{1});
  REQUIRE(h2.valid());
  CHECK((m.side_flags[h2.value] & kBoundary));
  m.flip(n);  // and back
  CHECK(m.has_edge(VertexId{0}, VertexId{2}));
  CHECK(check_topology(m).ok());
}

TEST_CASE("triangulation: flips across a grid, kill, compact") {
  TriangleStore m = grid3();
  CHECK(check_topology(m).ok());
  CHECK(check_delaunay(m, PlanarGeometry{&m.xy}).ok());
  // Flip every interior diagonal (all cells are squares: both diagonals legal).
  for (std::uint32_t j = 0; j < 2; ++j)
    for (std::uint32_t i = 0; i < 2; ++i) {
      const VertexId a{3 * j + i}, c{3 * j + i + 4};
      m.flip(m.side_between(a, c));
      CHECK(check_topology(m).ok());
      CHECK(m.has_edge(VertexId{a.value + 1}, VertexId{a.value + 3}));
    }
  // Every interior vertex (4) rotates fully: side_between finds all 8 neighbours' edges.
  int found = 0;
  for (std::uint32_t v = 0; v < 9; ++v)
    if (m.has_edge(VertexId{4}, VertexId{v})) ++found;
  CHECK(found == 6);  // 1, 2, 3, 5, 6, 7: the diagonals 0-4 and 4-8 became 1-3 and 5-7
  CHECK_FALSE(m.has_edge(VertexId{0}, VertexId{4}));
  CHECK_FALSE(m.has_edge(VertexId{4}, VertexId{8}));
  // Remove the corner triangles at 0 and 8 (the ear cut off by each flip):
  // the rest stays a manifold disc and 0, 8 become isolated.
  const TriId t0 = tri_of(m.out_side[0]), nb = tri_of(m.out_side[8]);
  m.kill_triangle(t0);
  m.kill_triangle(nb);
  CHECK_FALSE(m.out_side[0].valid());
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  CHECK(m.num_triangles() == 6);
  const TriId t = m.add_triangle(VertexId{0}, VertexId{1}, VertexId{3});  // reuses a slot
  CHECK(t == nb);
  m.kill_triangle(t);
  m.compact();
  CHECK(m.num_slots() == 6);
  CHECK(m.free_tris.empty());
  CHECK(check_topology(m).ok());
}

TEST_CASE("triangulation: checkers catch broken invariants") {
  TriangleStore m = unit_square_02();
  m.twin[0] = Side{4};
  CHECK_FALSE(check_topology(m).ok());
  m = unit_square_02();
  std::swap(m.corner[0], m.corner[1]);  // clockwise triangle
  CHECK_FALSE(check_topology(m).ok());
  m = unit_square_02();
  m.xy[3] = {0.9, 0.1};  // vertex 3 now inside the circle of (0,1,2)... and its triangle inverted
  CHECK_FALSE(check_topology(m).ok());
  TriangleStore d;
  REQUIRE(build_triangulation({{0, 0}, {4, 0}, {2, 1}, {2, -1}}, {{0, 3, 1}, {0, 1, 2}}, d));
  CHECK(check_topology(d).ok());
  CHECK_FALSE(check_delaunay(d, PlanarGeometry{&d.xy}).ok());  // 2 and 3 see each other: flat triangles
  d.set_edge_flags(d.side_between(VertexId{0}, VertexId{1}), kConstrained);
  CHECK(check_delaunay(d, PlanarGeometry{&d.xy}).ok());
  CHECK(check_constraints(d, {{VertexId{1}, VertexId{0}}}).ok());
  CHECK_FALSE(check_constraints(d, {{VertexId{2}, VertexId{3}}}).ok());
  TriangleStore bad;
  CHECK_FALSE(build_triangulation({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}, {0, 1, 2}}, bad));
}

TEST_CASE("triangulation: sort_spatially renumbers along the curve and keeps the mesh") {
  TriangleStore m;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  for (int i = 0; i < 3000; ++i) m.add_vertex({U(rng), U(rng)});
  REQUIRE(delaunay(m).ok());
  // A dead slot (an interior triangle, so the mesh stays manifold): dropped.
  std::uint32_t hole = 0;
  double best = 1e300;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    const double d = norm(m.pos(m.vertex(TriId{t}, 0)) - Vec2{0.5, 0.5});
    if (d < best) best = d, hole = t;
  }
  m.kill_triangle(TriId{hole});
  m.rebuild_out_side();
  REQUIRE(check_topology(m).ok());
  const auto tri_set = [](const TriangleStore& s, const std::vector<Vec2>& xy) {
    std::set<std::array<double, 6>> out;  // by position: ids change
    for (std::uint32_t t = 0; t < s.num_slots(); ++t) {
      if (!s.alive(TriId{t})) continue;
      std::uint32_t e0 = 0;  // rotate to start at the lowest x for a key that ignores ids
      for (std::uint32_t e = 1; e < 3; ++e)
        if (xy[s.vertex(TriId{t}, e).value].x < xy[s.vertex(TriId{t}, e0).value].x) e0 = e;
      std::array<double, 6> k{};
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Vec2 p = xy[s.vertex(TriId{t}, (e0 + e) % 3).value];
        k[2 * e] = p.x, k[2 * e + 1] = p.y;
      }
      out.insert(k);
    }
    return out;
  };
  const std::vector<Vec2> xy0 = m.xy;
  const std::uint32_t nt = m.num_triangles();
  const auto before = tri_set(m, m.xy);
  // Total centroid-to-centroid distance in slot order: the curve (through
  // first corners) shortens it.
  const auto path = [](const TriangleStore& s) {
    double len = 0;
    Vec2 prev{0, 0};
    bool first = true;
    for (std::uint32_t t = 0; t < s.num_slots(); ++t) {
      if (!s.alive(TriId{t})) continue;
      const Vec2 c =
          (1.0 / 3) * (s.pos(s.vertex(TriId{t}, 0)) + s.pos(s.vertex(TriId{t}, 1)) + s.pos(s.vertex(TriId{t}, 2)));
      if (!first) len += norm(c - prev);
      prev = c, first = false;
    }
    return len;
  };
  const double path0 = path(m);
  std::vector<std::uint32_t> new_slot, new_vertex;
  m.sort_spatially(1000, new_slot, new_vertex);
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  CHECK(m.num_slots() == nt);
  CHECK(m.free_tris.empty());
  CHECK(new_slot[hole] == TriId::kNone);
  for (std::uint32_t v = 0; v < 1000; ++v) CHECK(new_vertex[v] == v);
  for (std::uint32_t v = 0; v < 3000; ++v) CHECK(m.xy[new_vertex[v]] == xy0[v]);
  CHECK(tri_set(m, m.xy) == before);
  CHECK(path(m) < 0.5 * path0);
  CHECK(check_delaunay(m, PlanarGeometry{&m.xy}).ok());
}

TEST_CASE("triangulation: sort_spatially on an empty store, with an isolated vertex, and far from the origin") {
  TriangleStore empty;
  std::vector<std::uint32_t> new_slot, new_vertex;
  empty.sort_spatially(0, new_slot, new_vertex);
  CHECK(new_slot.empty());
  CHECK(new_vertex.empty());
  // Two triangles far from the origin (1e300 apart would overflow a plain
  // span) plus a vertex no triangle uses: it goes last.
  TriangleStore m;
  REQUIRE(build_triangulation({{-1e300, -1e300}, {1e300, -1e300}, {1e300, 1e300}, {-1e300, 1e300}, {0, 0}},
                              {{0, 1, 2}, {0, 2, 3}}, m));
  m.rebuild_out_side();
  REQUIRE(check_topology(m).ok());
  m.sort_spatially(0, new_slot, new_vertex);
  CHECK(check_topology(m).ok());
  CHECK(new_vertex[4] == 4);
  CHECK(m.xy[4] == Vec2{0, 0});
  CHECK(m.num_triangles() == 2);
}

TEST_CASE("side_between: a corrupt fan that never comes back ends, with the overrun said") {
  // the quality floor's undo once left twins that sent the walk round a vertex
  // into a cycle without its start; side_between looped for ever. Now it gives up after
  // the store's size, and says so.
  TriangleStore m = grid3();
  const VertexId c{4};   // the centre: a closed fan of six triangles
  REQUIRE(m.out_side_ok(c));
  const Side s0 = m.out_side[c.value];
  const Side s1 = m.twin[prev(s0).value];
  const Side s2 = m.twin[prev(s1).value];
  const Side s3 = m.twin[prev(s2).value];
  REQUIRE((s1.valid() && s2.valid() && s3.valid()));
  bool overrun = false;
  CHECK(!m.side_between(c, VertexId{2}, &overrun).valid());   // 2 is no neighbour of 4
  CHECK(!overrun);
  m.twin[prev(s3).value] = s1;   // s1 -> s2 -> s3 -> s1 -> ...: never back to s0
  CHECK(!m.side_between(c, VertexId{2}, &overrun).valid());
  CHECK(overrun);
}

TEST_CASE("for_each_fan_side: a closed fan, an open one at the hull, a stop, a lone triangle") {
  TriangleStore m = grid3();
  std::vector<Side> seen;
  const auto collect = [&seen](Side s) { seen.push_back(s); };
  // The centre: six triangles, counter-clockwise, back at the start.
  const VertexId c{4};
  CHECK(for_each_fan_side(m, m.out_side[c.value], collect) == FanEnd::Closed);
  REQUIRE(seen.size() == 6);
  std::set<std::uint32_t> tris;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    CHECK(m.org(seen[i]) == c);
    tris.insert(tri_of(seen[i]).value);
    if (i + 1 < seen.size()) CHECK(m.dest(seen[i + 1]) == m.apex(seen[i]));
  }
  CHECK(tris.size() == 6);
  // The middle of the bottom row (vertex 1): open, three triangles, whichever side it
  // starts from, counter-clockwise to the hull first, then clockwise from the start.
  const VertexId b{1};
  std::vector<Side> fan;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.corner[s] == b) fan.push_back(Side{s});
  REQUIRE(fan.size() == 3);
  for (Side start : fan) {
    seen.clear();
    CHECK(for_each_fan_side(m, start, collect) == FanEnd::Open);
    REQUIRE(seen.size() == 3);
    CHECK(seen.front() == start);
    tris.clear();
    for (Side s : seen) {
      CHECK(m.org(s) == b);
      tris.insert(tri_of(s).value);
    }
    CHECK(tris.size() == 3);
  }
  // A false from the function stops the walk where it is.
  seen.clear();
  CHECK(for_each_fan_side(m, m.out_side[c.value], [&seen](Side s) {
          seen.push_back(s);
          return seen.size() < 2;
        }) == FanEnd::Stopped);
  CHECK(seen.size() == 2);
  // A store of one triangle: the open fan holds every slot and still ends as Open.
  TriangleStore one;
  REQUIRE(build_triangulation({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}}, one));
  seen.clear();
  CHECK(for_each_fan_side(one, side_of(TriId{0}, 1), collect) == FanEnd::Open);
  CHECK(seen.size() == 1);
}

TEST_CASE("for_each_fan_side: a corrupt fan stops within the store's slots") {
  TriangleStore m = grid3();
  const VertexId c{4};
  const Side s0 = m.out_side[c.value];
  const Side s1 = m.twin[prev(s0).value];
  const Side s2 = m.twin[prev(s1).value];
  const Side s3 = m.twin[prev(s2).value];
  REQUIRE((s1.valid() && s2.valid() && s3.valid()));
  m.twin[prev(s3).value] = s1;  // s1 -> s2 -> s3 -> s1 -> ...: never back to s0, no hull
  std::size_t calls = 0;
  CHECK(for_each_fan_side(m, s0, [&calls](Side) { ++calls; }) == FanEnd::Corrupt);
  CHECK(calls == m.num_slots());
  // The same loop met clockwise, after an open counter-clockwise part.
  TriangleStore o = grid3();
  const Side t0 = o.out_side[c.value];
  const Side t1 = o.twin[t0.value];            // -> c in the triangle clockwise of t0
  REQUIRE(t1.valid());
  const Side back = next(t1);                   // leaves c, clockwise of t0
  o.twin[prev(t0).value] = Side{};              // open counter-clockwise right after t0
  o.twin[back.value] = prev(back);              // clockwise from back: back to back, for ever
  calls = 0;
  CHECK(for_each_fan_side(o, t0, [&calls](Side) { ++calls; }) == FanEnd::Corrupt);
  CHECK(calls == o.num_slots());
}
