// The one point location of mesh/ (mesh/locate.h): the walk ends in a triangle holding the
// point within its step bound, the fallback scan finds one when the bound is cut short
// and does not pass a wall, and the barycentric weights give the point back.
#include <doctest/doctest.h>

#include <random>

#include "mesh/delaunay.h"
#include "mesh/locate.h"

using namespace sm;

namespace {

struct TurningWalker : StoreWalker {
  std::uint32_t turn = 0;
  std::uint32_t first_side(std::uint32_t, std::uint64_t) { return turn = (turn + 1) % 3; }
};

TriangleStore random_delaunay(std::uint64_t seed, int n) {
  TriangleStore m;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  for (int i = 0; i < n; ++i) m.add_vertex({U(rng), U(rng)});
  REQUIRE(delaunay(m).ok());
  return m;
}

}  // namespace

TEST_CASE("locate: the walk finds the triangle within the triangle count") {
  const TriangleStore m = random_delaunay(3, 500);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> U(0.01, 0.99);
  TurningWalker w{{m}};
  std::uint32_t hint = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec2 p{U(rng), U(rng)};
    const WalkResult r = walk_to(w, p, hint, m.num_slots());
    REQUIRE(r.end == WalkEnd::Found);
    CHECK(r.steps <= m.num_slots());
    CHECK(walker_contains(w, r.tri, p));
    hint = r.tri;
  }
}

TEST_CASE("locate: a walk cut short ends at its limit, and the scan finds the triangle") {
  const TriangleStore m = random_delaunay(5, 200);
  TurningWalker w{{m}};
  const Vec2 p{0.5, 0.5};
  std::uint32_t far = 0;   // a triangle that does not hold p, so the walk has to step
  while (walker_contains(w, far, p)) ++far;
  const WalkResult r = walk_to(w, p, far, 0);
  CHECK(r.end == WalkEnd::StepLimit);
  CHECK(r.tri == far);
  const TriId t = scan_for(w, p, TriId{far});
  REQUIRE(t.valid());
  CHECK(walker_contains(w, t.value, p));
}

TEST_CASE("locate: hull sides are walls unless passed over; the scan stops at walls") {
  const TriangleStore m = random_delaunay(6, 100);
  const Vec2 beyond{2.0, 0.5};
  TurningWalker walled{{m}};
  CHECK(walk_to(walled, beyond, 0, m.num_slots()).end == WalkEnd::Blocked);
  CHECK(!scan_for(walled, beyond, TriId{0}).valid());
  TurningWalker clamped{{m, nullptr, true, true}};
  const WalkResult r = walk_to(clamped, beyond, 0, m.num_slots());
  CHECK(r.end == WalkEnd::Found);   // the hull triangle where no side may be crossed
  bool on_hull = false;
  for (std::uint32_t e = 0; e < 3; ++e) on_hull = on_hull || !m.twin[3 * r.tri + e].valid();
  CHECK(on_hull);
}

TEST_CASE("locate: barycentric weights") {
  const Vec2 a{0, 0}, b{4, 0}, c{0, 2}, p{1, 0.5};
  const std::array<double, 3> w = barycentric(a, b, c, p);
  CHECK(w[0] + w[1] + w[2] == doctest::Approx(1.0));
  CHECK(w[0] * a.x + w[1] * b.x + w[2] * c.x == doctest::Approx(p.x));
  CHECK(w[0] * a.y + w[1] * b.y + w[2] * c.y == doctest::Approx(p.y));
  const std::array<double, 3> flat = barycentric(a, c, b, p);   // clockwise: the fallback thirds
  CHECK(flat[0] == doctest::Approx(1.0 / 3));
}

TEST_CASE("locate: the straight walk from a centroid ends in the triangle holding the point") {
  const TriangleStore m = random_delaunay(7, 300);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(0.2, 0.8);
  int crossed = 0;
  for (std::uint32_t t = 0; t < 100; ++t) {
    const Vec2 g = (m.pos(m.vertex(TriId{t}, 0)) + m.pos(m.vertex(TriId{t}, 1)) + m.pos(m.vertex(TriId{t}, 2))) / 3.0;
    const Vec2 p{U(rng), U(rng)};
    SegmentWalker w{m, g, p};
    const WalkResult r = walk_to(w, p, t, m.num_slots());
    REQUIRE(r.end == WalkEnd::Found);
    StoreWalker look{m};
    CHECK(walker_contains(look, r.tri, p));
    crossed += r.steps > 0;
  }
  CHECK(crossed > 50);
}
