// Delaunay of point sets, checked by the invariant checkers, Euler's count
// and (for small sets) the global empty-circle property.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>

#include "mesh/check.h"
#include "mesh/delaunay.h"

using namespace sm;

namespace {

std::uint32_t hull_sides(const TriangleStore& m) {
  std::uint32_t h = 0;
  for (const Side& s : m.twin) h += !s.valid();
  return h;
}

// Canonical triangle set: each rotated to start at its smallest id, sorted.
std::vector<std::array<std::uint32_t, 3>> canonical(const TriangleStore& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    std::array<std::uint32_t, 3> c{m.vertex(TriId{t}, 0).value, m.vertex(TriId{t}, 1).value,
                                   m.vertex(TriId{t}, 2).value};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Every triangle's circumcircle is empty of every point (exact).
bool globally_delaunay(const TriangleStore& m) {
  const PlanarGeometry g{&m.xy};
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    for (std::uint32_t v = 0; v < m.num_vertices(); ++v)
      if (g.in_circle(m.vertex(TriId{t}, 0), m.vertex(TriId{t}, 1), m.vertex(TriId{t}, 2), VertexId{v}) ==
          Sign::Positive)
        return false;
  return true;
}

void check_all(const TriangleStore& m, std::uint32_t distinct) {
  INFO(check_topology(m).error);
  REQUIRE(check_topology(m).ok());
  const PlanarGeometry g{&m.xy};
  INFO(check_delaunay(m, g, true).error);
  REQUIRE(check_delaunay(m, g, true).ok());
  // Euler: a triangulation of n points with h on the hull boundary has
  // 2n - 2 - h triangles (h counts hull sides, collinear hull points included).
  CHECK(m.num_triangles() == 2 * distinct - 2 - hull_sides(m));
}

}  // namespace

TEST_CASE("delaunay: small sets") {
  TriangleStore m;
  m.xy = {{0, 0}, {1, 0}, {0, 1}};
  REQUIRE(delaunay(m).ok());
  check_all(m, 3);
  CHECK(m.num_triangles() == 1);
  m.clear();
  m.xy = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // cocircular: the tie-break picks one diagonal
  REQUIRE(delaunay(m).ok());
  check_all(m, 4);
  CHECK(m.num_triangles() == 2);
  m.clear();
  m.xy = {{0, 0}, {1, 1}, {2, 2}};
  CHECK_FALSE(delaunay(m).ok());
  CHECK(m.num_triangles() == 0);
  m.clear();
  m.xy = {{0, 0}, {1, 1}};
  CHECK_FALSE(delaunay(m).ok());
  m.clear();
  m.xy = {{0, 0}, {1, NAN}, {2, 0}, {0, 3}};
  CHECK_FALSE(delaunay(m).ok());
}

TEST_CASE("delaunay: uniform random points, global empty circles and determinism") {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> U(0, 1);
  for (int n : {10, 100, 300}) {
    TriangleStore m;
    for (int i = 0; i < n; ++i) m.add_vertex({U(rng), U(rng)});
    const auto r = delaunay(m);
    REQUIRE(r.ok());
    CHECK(r.duplicates.empty());
    check_all(m, n);
    CHECK(globally_delaunay(m));
    TriangleStore m2;
    m2.xy = m.xy;
    m2.out_side.resize(n);
    REQUIRE(delaunay(m2, DelaunayOptions{12345}).ok());  // another insertion order
    CHECK(canonical(m) == canonical(m2));
  }
  TriangleStore big;
  for (int i = 0; i < 50000; ++i) big.add_vertex({U(rng), U(rng)});
  const auto r = delaunay(big);
  REQUIRE(r.ok());
  check_all(big, 50000);
  CHECK(r.stats.walk_steps < 50000 * 10);  // BRIO + walk: a few steps per point
}

TEST_CASE("delaunay: grids are massively cocircular; result is unique") {
  for (int k : {2, 7, 40}) {
    TriangleStore m;
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) m.add_vertex({i * 0.1, j * 0.1});
    REQUIRE(delaunay(m).ok());
    check_all(m, k * k);
    CHECK(m.num_triangles() == 2 * (k - 1) * (k - 1));
    CHECK(globally_delaunay(m));
    TriangleStore m2;
    m2.xy = m.xy;
    m2.out_side.resize(m.xy.size());
    // Another insertion order: ties are broken by id, so the result is the same.
    REQUIRE(delaunay(m2, DelaunayOptions{99}).ok());
    CHECK(canonical(m) == canonical(m2));
  }
  // Integer points on one circle (x^2 + y^2 = 5^2 * 13): all cocircular.
  TriangleStore c;
  for (int x = -20; x <= 20; ++x)
    for (int y = -20; y <= 20; ++y)
      if (x * x + y * y == 325) c.add_vertex({double(x), double(y)});
  c.add_vertex({0.5, 0.25});
  REQUIRE(delaunay(c).ok());
  check_all(c, c.num_vertices());
}

TEST_CASE("delaunay: collinear runs, points on hull edges, near-collinear at 1e-16") {
  TriangleStore m;
  for (int i = 0; i < 100; ++i) m.add_vertex({i * 0.01, 0});      // a line...
  m.add_vertex({0.5, 1});                                          // ...and one apex
  for (int i = 1; i < 50; ++i) m.add_vertex({0.5 * i / 50.0, i / 50.0});  // points on the left side
  REQUIRE(delaunay(m).ok());
  check_all(m, m.num_vertices());
  CHECK(globally_delaunay(m));
  // Points within an ulp of a line: orientation decided exactly.
  TriangleStore n;
  const double u = std::ldexp(1.0, -52);
  for (int i = 0; i < 200; ++i) n.add_vertex({0.5 + i * u * 3, 0.5 + i * u * 3 + ((i * 7) % 5 - 2) * u});
  n.add_vertex({0.2, 0.9});
  n.add_vertex({0.9, 0.1});
  REQUIRE(delaunay(n).ok());
  check_all(n, n.num_vertices());
  CHECK(globally_delaunay(n));
}

TEST_CASE("delaunay: duplicates are reported, not inserted") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  TriangleStore m;
  for (int i = 0; i < 1000; ++i) m.add_vertex({U(rng), U(rng)});
  for (int i = 0; i < 1000; i += 10) m.add_vertex(m.xy[i]);  // ids 1000.. copy 0, 10, 20, ...
  m.add_vertex(m.xy[0]);                                      // a third copy of 0
  const auto r = delaunay(m);
  REQUIRE(r.ok());
  CHECK(r.duplicates.size() == 101);
  std::set<std::uint32_t> dup_ids;
  for (auto d : r.duplicates) {
    CHECK(m.xy[d.dup.value] == m.xy[d.kept.value]);
    CHECK(d.dup != d.kept);
    CHECK_FALSE(m.out_side[d.dup.value].valid());  // not in the mesh
    CHECK(m.out_side[d.kept.value].valid());
    dup_ids.insert(d.dup.value);
  }
  CHECK(dup_ids.size() == 101);
  check_all(m, 1000);
}

TEST_CASE("delaunay: clustered points at wildly different scales") {
  std::mt19937_64 rng(8);
  std::normal_distribution<double> N(0, 1);
  TriangleStore m;
  const Vec2 centres[] = {{0, 0}, {1, 0}, {0.3, 0.7}, {1e6, 1e6}};
  for (int c = 0; c < 4; ++c)
    for (int i = 0; i < 500; ++i) {
      const double s = std::pow(10.0, -(i % 12));
      m.add_vertex({centres[c].x + s * N(rng), centres[c].y + s * N(rng)});
    }
  const auto r = delaunay(m);
  REQUIRE(r.ok());
  check_all(m, m.num_vertices() - static_cast<std::uint32_t>(r.duplicates.size()));
}

TEST_CASE("delaunay: Hilbert index is a curve through adjacent cells; BRIO order is a permutation") {
  for (int bits : {4, 8}) {
    const std::uint32_t side = 1u << bits;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> cell(side * side, {~0u, ~0u});
    for (std::uint32_t x = 0; x < side; ++x)
      for (std::uint32_t y = 0; y < side; ++y) {
        const std::uint32_t d = hilbert_index(x, y, bits);
        REQUIRE(d < side * side);
        REQUIRE(cell[d].first == ~0u);
        cell[d] = {x, y};
      }
    for (std::size_t d = 1; d < cell.size(); ++d) {
      const int dx = std::abs(int(cell[d].first) - int(cell[d - 1].first));
      const int dy = std::abs(int(cell[d].second) - int(cell[d - 1].second));
      REQUIRE(dx + dy == 1);
    }
  }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Vec2> xy(5000);
  for (auto& p : xy) p = {U(rng), U(rng)};
  auto order = brio_order(xy, 7);
  CHECK(order == brio_order(xy, 7));
  std::sort(order.begin(), order.end());
  for (std::uint32_t i = 0; i < order.size(); ++i) REQUIRE(order[i] == i);
}

TEST_CASE("delaunay: coordinates near the ends of the double range") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  for (double scale : {1e-300, 1e300, 1.7e308}) {
    TriangleStore m;
    for (int i = 0; i < 300; ++i) m.add_vertex({scale * U(rng), scale * U(rng)});
    for (int i = 0; i < 20; ++i) m.add_vertex({scale * (-0.5 + 0.05 * i), scale * 0.25});  // a collinear run
    const auto r = delaunay(m);
    REQUIRE(r.ok());
    check_all(m, m.num_vertices());
  }
}

TEST_CASE("delaunay: random small lattices (duplicates, collinear and cocircular everywhere)") {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 300; ++trial) {
    const int side = 2 + static_cast<int>(rng() % 7), n = 3 + static_cast<int>(rng() % 60);
    TriangleStore m;
    for (int i = 0; i < n; ++i) m.add_vertex({double(rng() % side) * 0.1, double(rng() % side) * 0.3});
    const auto r = delaunay(m, DelaunayOptions{rng()});
    std::set<std::pair<double, double>> distinct;
    for (const Vec2& p : m.xy) distinct.insert({p.x, p.y});
    if (!r.ok()) {
      // Only when every point is collinear (or there are fewer than 3).
      bool collinear = true;
      for (std::uint32_t i = 2; i < m.num_vertices() && collinear; ++i)
        for (std::uint32_t j = 1; j < i && collinear; ++j)
          collinear = orient2d(m.xy[0], m.xy[j], m.xy[i]) == Sign::Zero || m.xy[0] == m.xy[j];
      CHECK(collinear);
      continue;
    }
    CHECK(r.duplicates.size() == n - distinct.size());
    check_all(m, static_cast<std::uint32_t>(distinct.size()));
    CHECK(globally_delaunay(m));
    TriangleStore m2;
    m2.xy = m.xy;
    REQUIRE(delaunay(m2, DelaunayOptions{rng()}).ok());
    // Duplicates may keep a different copy; compare when there are none.
    if (r.duplicates.empty()) CHECK(canonical(m) == canonical(m2));
  }
}
