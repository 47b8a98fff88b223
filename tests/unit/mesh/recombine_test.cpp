// mesh/recombine: pairs on a split square, every triangle paired on a Delaunay square
// with an even triangle count (Matching), the simple pass's leftovers isolated, embedded
// edges kept, the corner quality.
#include "mesh/recombine.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "mesh/delaunay.h"
#include "mesh/triangulation.h"

namespace recombine_testing {

// A Delaunay triangulation of an n x n grid of points slightly perturbed (fixed, so the
// same for every run) as triangles; xy and xyz of its points.
struct Grid {
  std::vector<sm::Vec2> xy;
  std::vector<sm::Vec3> xyz;
  std::vector<std::array<std::uint32_t, 3>> tris;
};

Grid delaunay_grid(int n) {
  Grid g;
  sm::TriangleStore m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool inner = i > 0 && j > 0 && i + 1 < n && j + 1 < n;
      const double dx = inner ? 0.21 * std::sin(12.9898 * i + 78.233 * j) : 0.0;
      const double dy = inner ? 0.21 * std::cos(39.3468 * i + 11.135 * j) : 0.0;
      m.add_vertex({(i + dx) / (n - 1), (j + dy) / (n - 1)});
    }
  REQUIRE(sm::delaunay(m).ok());
  g.xy = m.xy;
  for (const sm::Vec2 p : g.xy) g.xyz.push_back({p.x, p.y, 0});
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(sm::TriId{t}))
      g.tris.push_back(
          {m.vertex(sm::TriId{t}, 0).value, m.vertex(sm::TriId{t}, 1).value, m.vertex(sm::TriId{t}, 2).value});
  return g;
}

double area(const Grid& g, const std::vector<std::uint32_t>& poly) {
  double a = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const sm::Vec2 p = g.xy[poly[k]], q = g.xy[poly[(k + 1) % poly.size()]];
    a += p.x * q.y - p.y * q.x;
  }
  return 0.5 * a;
}

// Whether two triangles of the list share an edge.
bool any_adjacent(const std::vector<std::array<std::uint32_t, 3>>& t) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const auto& x : t)
    for (int e = 0; e < 3; ++e)
      if (!seen.insert(std::minmax(x[e], x[(e + 1) % 3])).second) return true;
  return false;
}

}  // namespace recombine_testing

TEST_CASE("recombine: the corner quality") {
  CHECK(sm::quad_quality({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}) == doctest::Approx(1.0));
  // A rhombus with 60 and 120 degree corners: 1 - 30 / 90.
  const double s = std::sqrt(3.0) / 2;
  CHECK(sm::quad_quality({0, 0, 0}, {1, 0, 0}, {1.5, s, 0}, {0.5, s, 0}) == doctest::Approx(2.0 / 3));
}

TEST_CASE("recombine: two triangles of a square become one counter-clockwise quadrangle") {
  const std::vector<sm::Vec2> xy = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<sm::Vec3> xyz = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<std::array<std::uint32_t, 3>> tris = {{0, 1, 2}, {0, 2, 3}};
  for (auto algo : {sm::RecombineAlgorithm::Simple, sm::RecombineAlgorithm::Matching}) {
    sm::RecombineOptions o;
    o.algorithm = algo;
    const sm::RecombineResult r = sm::recombine(tris, xyz, xy, {}, o);
    REQUIRE(r.quads.size() == 1);
    CHECK(r.triangles.empty());
    const auto& q = r.quads[0];
    std::array<std::uint32_t, 4> sorted = q;
    std::sort(sorted.begin(), sorted.end());
    CHECK(sorted == std::array<std::uint32_t, 4>{0, 1, 2, 3});
    recombine_testing::Grid g;
    g.xy = xy;
    CHECK(recombine_testing::area(g, {q[0], q[1], q[2], q[3]}) == doctest::Approx(1.0));
  }
  // The diagonal held by an embedded curve stays.
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> fixed = {{0, 2}};
  const sm::RecombineResult kept = sm::recombine(tris, xyz, xy, fixed, {});
  CHECK(kept.quads.empty());
  CHECK(kept.triangles.size() == 2);
}

TEST_CASE("recombine: a Delaunay square, simple and matching") {
  using namespace recombine_testing;
  const Grid g = delaunay_grid(12);
  const std::size_t nt = g.tris.size();
  double total = 0;
  for (const auto& t : g.tris) total += area(g, {t[0], t[1], t[2]});
  sm::RecombineOptions simple;
  simple.algorithm = sm::RecombineAlgorithm::Simple;
  const sm::RecombineResult s = sm::recombine(g.tris, g.xyz, g.xy, {}, simple);
  const sm::RecombineResult mt = sm::recombine(g.tris, g.xyz, g.xy, {}, {});
  for (const sm::RecombineResult* r : {&s, &mt}) {
    CHECK(2 * r->quads.size() + r->triangles.size() == nt);
    // The greedy pass is maximal: no two triangles left side by side.
    CHECK_FALSE(any_adjacent(r->triangles));
    double sum = 0;
    for (const auto& q : r->quads) {
      const double a = area(g, {q[0], q[1], q[2], q[3]});
      CHECK(a > 0);
      sum += a;
      CHECK(sm::quad_quality(g.xyz[q[0]], g.xyz[q[1]], g.xyz[q[2]], g.xyz[q[3]]) >= 0.1);
    }
    for (const auto& t : r->triangles) sum += area(g, {t[0], t[1], t[2]});
    CHECK(sum == doctest::Approx(total));
  }
  // 242 triangles (an even count): the matching pairs them all, the simple pass does not.
  CHECK(nt % 2 == 0);
  CHECK(mt.triangles.empty());
  CHECK(mt.augmentations > 0);
  CHECK(s.triangles.size() > 0);
  MESSAGE("simple leaves " << s.triangles.size() << " of " << nt << " triangles, matching " << mt.triangles.size());
}
