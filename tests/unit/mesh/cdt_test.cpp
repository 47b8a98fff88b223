// Edge recovery by swaps (crossings detected, collinear vertices split) and
// removal of outside triangles; every case ends with the checkers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "mesh/cdt.h"
#include "mesh/check.h"
#include "mesh/delaunay.h"

using namespace sm;

namespace {

void check_cdt(const TriangleStore& m, const std::vector<Edge>& constrained) {
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  INFO(check_constraints(m, constrained).error);
  REQUIRE(check_constraints(m, constrained).ok());
  // Constrained Delaunay: every non-constrained edge locally Delaunay (ties by id).
  INFO(check_delaunay(m, PlanarGeometry{&m.xy}, true).error);
  REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
}

double area(const TriangleStore& m) {
  double a = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    const Vec2 p = m.pos(m.vertex(TriId{t}, 0)), q = m.pos(m.vertex(TriId{t}, 1)), r = m.pos(m.vertex(TriId{t}, 2));
    a += 0.5 * cross(q - p, r - p);
  }
  return a;
}

}  // namespace

TEST_CASE("cdt: long thin constraints through random points") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  TriangleStore m;
  for (int i = 0; i < 3000; ++i) m.add_vertex({U(rng), U(rng)});
  std::vector<Edge> edges;
  for (int k = 0; k < 25; ++k) {  // nearly horizontal, distinct heights: no two cross
    const double y = 0.02 + 0.038 * k;
    const VertexId a = m.add_vertex({0.01 + 0.001 * k, y}), b = m.add_vertex({0.99 - 0.001 * k, y + 0.011});
    edges.push_back({a, b});
  }
  REQUIRE(delaunay(m).ok());
  const PlanarGeometry g{&m.xy};
  const auto r = recover_edges(m, g, edges);
  REQUIRE(r.ok());
  CHECK(r.clean());
  CHECK(r.stats.flips > 100);
  check_cdt(m, edges);
  // Recovering again changes nothing.
  const auto r2 = recover_edges(m, g, edges);
  CHECK(r2.clean());
  CHECK(r2.stats.flips == 0);
  CHECK(r2.stats.already_present == edges.size());
}

TEST_CASE("cdt: a constraint crossing a constrained edge is reported, not swapped") {
  TriangleStore m;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) m.add_vertex({i + 0.01 * j, j + 0.013 * i});  // perturbed grid
  const VertexId a = m.add_vertex({-1, 2.5}), b = m.add_vertex({6, 2.7});   // roughly horizontal
  const VertexId c = m.add_vertex({2.5, -1}), d = m.add_vertex({2.7, 6});   // roughly vertical
  REQUIRE(delaunay(m).ok());
  const PlanarGeometry g{&m.xy};
  const auto r = recover_edges(m, g, {{a, b}, {c, d}});
  REQUIRE(r.ok());
  REQUIRE(r.crossings.size() == 1);
  CHECK(r.crossings[0].edge == 1);
  CHECK(r.crossings[0].other == 0);
  CHECK(m.has_edge(a, b));
  check_cdt(m, {{a, b}});
  CHECK_FALSE(m.has_edge(c, d));
}

TEST_CASE("cdt: vertices exactly on a constraint split it") {
  TriangleStore m;
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) m.add_vertex({double(i), double(j)});
  REQUIRE(delaunay(m).ok());
  const PlanarGeometry g{&m.xy};
  const VertexId v00{0}, v_diag{29 * 30 + 29}, v_thin{1 * 30 + 29}, v_row{29};
  const auto r = recover_edges(m, g, {{v00, v_diag}, {v00, v_thin}, {VertexId{30}, VertexId{30 + 29}}});
  REQUIRE(r.ok());
  CHECK(r.crossings.empty());
  // The diagonal passes through (i, i) for i = 1..28, the row through 28 vertices.
  CHECK(r.touching.size() == 28 + 28);
  std::vector<Edge> sub;
  for (std::uint32_t i = 0; i < 29; ++i) sub.push_back({VertexId{31 * i}, VertexId{31 * (i + 1)}});
  for (std::uint32_t i = 0; i < 29; ++i) sub.push_back({VertexId{30 + i}, VertexId{31 + i}});
  sub.push_back({v00, v_thin});  // slope 1/29: through no vertex
  check_cdt(m, sub);
  (void)v_row;
}

TEST_CASE("cdt: random non-crossing polygon edges at many scales") {
  // A star-shaped polygon around the centre with radii spanning 1e-6..1:
  // its edges never cross; points scattered inside and out.
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> U(0, 1);
  TriangleStore m;
  const int n = 400;
  std::vector<VertexId> poly;
  for (int k = 0; k < n; ++k) {
    const double th = 2 * M_PI * k / n, r = 0.3 + 0.2 * U(rng) + (k % 7 == 0 ? 1e-6 * U(rng) : 0);
    poly.push_back(m.add_vertex({0.5 + r * std::cos(th), 0.5 + r * std::sin(th)}));
  }
  for (int i = 0; i < 2000; ++i) m.add_vertex({U(rng), U(rng)});
  REQUIRE(delaunay(m).ok());
  std::vector<Edge> edges;
  for (int k = 0; k < n; ++k) edges.push_back({poly[k], poly[(k + 1) % n]});
  const PlanarGeometry g{&m.xy};
  const auto r = recover_edges(m, g, edges);
  REQUIRE(r.ok());
  // Random interior points may fall exactly on an edge only with probability 0.
  CHECK(r.clean());
  check_cdt(m, edges);
  const double before = area(m);
  const auto d = remove_outside(m, g, {Loop{poly, false}});
  REQUIRE(d.ok());
  CHECK(d.removed > 0);
  CHECK(check_topology(m).ok());
  CHECK(check_constraints(m, edges).ok());
  double poly_area = 0;
  for (int k = 0; k < n; ++k) poly_area += 0.5 * cross(m.pos(poly[k]), m.pos(poly[(k + 1) % n]));
  CHECK(area(m) == doctest::Approx(poly_area).epsilon(1e-12));
  CHECK(area(m) < before);
}

TEST_CASE("cdt: outer loop with holes, either orientation; inconsistent loops fail") {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> U(0, 1);
  TriangleStore m;
  auto square = [&](double x0, double y0, double s, int per_side) {
    std::vector<VertexId> v;
    const Vec2 c[4] = {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
    for (int e = 0; e < 4; ++e)
      for (int k = 0; k < per_side; ++k)
        v.push_back(m.add_vertex(c[e] + (double(k) / per_side) * (c[(e + 1) % 4] - c[e])));
    return v;
  };
  auto outer = square(0, 0, 1, 10);
  auto hole1 = square(0.2, 0.2, 0.2, 3);
  auto hole2 = square(0.6, 0.5, 0.3, 4);
  std::reverse(hole1.begin(), hole1.end());  // orientation must not matter
  for (int i = 0; i < 500; ++i) m.add_vertex({U(rng), U(rng)});
  REQUIRE(delaunay(m).ok());
  std::vector<Edge> edges;
  for (const std::vector<VertexId>* l : {&outer, &hole1, &hole2})
    for (std::size_t k = 0; k < l->size(); ++k) edges.push_back({(*l)[k], (*l)[(k + 1) % l->size()]});
  const PlanarGeometry g{&m.xy};
  const auto r = recover_edges(m, g, edges);
  REQUIRE(r.ok());
  // Random points may land exactly on an axis-aligned side only by chance.
  CHECK(r.crossings.empty());
  check_cdt(m, edges);
  TriangleStore copy = m;
  const auto d = remove_outside(m, g, {Loop{outer, false}, Loop{hole1, true}, Loop{hole2, true}});
  REQUIRE(d.ok());
  INFO(check_topology(m).error);
  CHECK(check_topology(m).ok());
  CHECK(area(m) == doctest::Approx(1 - 0.04 - 0.09));
  // The same loop as outer boundary and as hole: contradictory.
  const PlanarGeometry gc{&copy.xy};
  const auto bad = remove_outside(copy, gc, {Loop{outer, false}, Loop{hole2, true}, Loop{outer, true}});
  CHECK_FALSE(bad.ok());
  // A hole lying outside the outer loop (here: the outer square is the
  // small one) changes nothing and is no error.
  TriangleStore only = copy;
  const auto d2 = remove_outside(only, gc, {Loop{hole2, false}, Loop{hole1, true}});
  REQUIRE(d2.ok());
  CHECK(area(only) == doctest::Approx(0.09));
  CHECK(copy.num_triangles() == m.num_triangles() + d.removed);  // unchanged on failure
}

namespace {

// Exact for small integers: proper crossing or overlap of two segments.
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 != o2 && o3 != o4 && o1 != Sign::Zero && o2 != Sign::Zero && o3 != Sign::Zero && o4 != Sign::Zero)
    return true;
  auto on = [](Vec2 p, Vec2 q, Vec2 r) {  // r on closed segment pq, collinear assumed
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  // Touching in the interior of either segment counts as meeting.
  if (o1 == Sign::Zero && on(a, b, c) && !(c == a) && !(c == b)) return true;
  if (o2 == Sign::Zero && on(a, b, d) && !(d == a) && !(d == b)) return true;
  if (o3 == Sign::Zero && on(c, d, a) && !(a == c) && !(a == d)) return true;
  if (o4 == Sign::Zero && on(c, d, b) && !(b == c) && !(b == d)) return true;
  return false;
}

}  // namespace

TEST_CASE("cdt: random lattices with random non-crossing constraints") {
  std::mt19937_64 rng(77);
  for (int trial = 0; trial < 150; ++trial) {
    const int side = 4 + static_cast<int>(rng() % 8);
    TriangleStore m;
    std::set<std::pair<int, int>> used;
    const int n = 10 + static_cast<int>(rng() % 60);
    for (int i = 0; i < n; ++i) {
      const int x = static_cast<int>(rng() % side), y = static_cast<int>(rng() % side);
      if (used.insert({x, y}).second) m.add_vertex({double(x), double(y)});
    }
    if (!delaunay(m).ok()) continue;
    // Greedy set of constraints that pairwise neither cross nor touch
    // (a vertex exactly on a constraint is fine: it gets split).
    std::vector<Edge> edges;
    for (int k = 0; k < 40; ++k) {
      const VertexId a{static_cast<std::uint32_t>(rng() % m.num_vertices())};
      const VertexId b{static_cast<std::uint32_t>(rng() % m.num_vertices())};
      if (a == b) continue;
      bool ok = true;
      for (auto [c, d] : edges)
        if (segments_meet(m.xy[a.value], m.xy[b.value], m.xy[c.value], m.xy[d.value])) ok = false;
      if (ok) edges.push_back({a, b});
    }
    const auto r = recover_edges(m, PlanarGeometry{&m.xy}, edges);
    REQUIRE(r.ok());
    REQUIRE(r.crossings.empty());
    INFO(check_topology(m).error);
    REQUIRE(check_topology(m).ok());
    REQUIRE(check_delaunay(m, PlanarGeometry{&m.xy}, true).ok());
    // Each constraint is present, or split through the vertices on it.
    for (std::uint32_t i = 0; i < edges.size(); ++i) {
      bool split = false;
      for (const auto& t : r.touching) split |= t.edge == i;
      if (!split) CHECK(check_constraints(m, {edges[i]}).ok());
    }
    // And a crossing constraint added now is reported.
    if (!edges.empty()) {
      const auto [a, b] = edges[0];
      for (std::uint32_t v = 0; v < m.num_vertices(); ++v)
        for (std::uint32_t w = v + 1; w < m.num_vertices(); ++w) {
          const Vec2 p = m.xy[v], q = m.xy[w];
          const Sign o1 = orient2d(m.xy[a.value], m.xy[b.value], p), o2 = orient2d(m.xy[a.value], m.xy[b.value], q);
          const Sign o3 = orient2d(p, q, m.xy[a.value]), o4 = orient2d(p, q, m.xy[b.value]);
          if (o1 != Sign::Zero && o2 != Sign::Zero && o1 != o2 && o3 != Sign::Zero && o4 != Sign::Zero && o3 != o4) {
            TriangleStore copy = m;
            const auto rc = recover_edges(copy, PlanarGeometry{&copy.xy}, {{VertexId{v}, VertexId{w}}});
            REQUIRE(rc.ok());
            const bool split0 =
                std::any_of(r.touching.begin(), r.touching.end(), [](const VertexOnEdge& t) { return t.edge == 0; });
            if (!split0) CHECK(!rc.crossings.empty());
            CHECK(check_topology(copy).ok());
            v = w = m.num_vertices();  // one probe per trial
          }
        }
    }
  }
}
