// Orientation and point-in-ring with exact predicates, including degenerate input.
#include "exact/ring.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace sm;

TEST_CASE("ring: orientation and inclusion") {
  const std::vector<Vec2> ccw{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  std::vector<Vec2> cw(ccw.rbegin(), ccw.rend());
  CHECK(ring_orientation(ccw) == Sign::Positive);
  CHECK(ring_orientation(cw) == Sign::Negative);
  const std::vector<Vec2> flat{{0, 0}, {1, 0}, {2, 0}};
  CHECK(ring_orientation(flat) == Sign::Zero);
  // A nearly degenerate sliver: the exact predicate still decides.
  const std::vector<Vec2> sliver{{0, 0}, {1, 1e-300}, {2, 0}, {1, -1e-300}};
  CHECK(ring_orientation(sliver) == Sign::Negative);   // over the top left to right: clockwise
  CHECK(point_in_ring(ccw, {1, 1}));
  CHECK_FALSE(point_in_ring(ccw, {3, 1}));
  CHECK_FALSE(point_in_ring(ccw, {2, 1}));   // on the boundary: outside
  CHECK_FALSE(point_in_ring(ccw, {0, 0}));
  CHECK(point_in_ring(cw, {1, 1}));          // orientation does not matter
  // A vertex exactly on the ray's line is counted once.
  const std::vector<Vec2> diamond{{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  CHECK(point_in_ring(diamond, {-0.5, 0}));
  CHECK_FALSE(point_in_ring(diamond, {-1.5, 0}));
}

TEST_CASE("ring: one edge's ray crossing") {
  CHECK(ray_crossing({0, 0}, {0, 2}, {-1, 1}) == RayCrossing::Crosses);   // going up, p on its left
  CHECK(ray_crossing({0, 2}, {0, 0}, {-1, 1}) == RayCrossing::Crosses);   // going down, p on its right
  CHECK(ray_crossing({0, 0}, {0, 2}, {1, 1}) == RayCrossing::Misses);     // the edge is behind p
  CHECK(ray_crossing({0, 0}, {0, 2}, {0, 1}) == RayCrossing::OnEdge);
  CHECK(ray_crossing({0, 0}, {0, 2}, {-1, 2}) == RayCrossing::Misses);    // half-open: the top end is out
  CHECK(ray_crossing({0, 0}, {0, 2}, {-1, 0}) == RayCrossing::Crosses);   // the bottom end is in
  CHECK(ray_crossing({0, 0}, {2, 0}, {-1, 0}) == RayCrossing::Misses);    // horizontal edges never count
  // Points within an ulp of a slanted edge: the answer is orient2d's, whatever a crossing
  // abscissa computed in floating point would say.
  const Vec2 a{0.1, 0.1}, b{0.7, 0.9};
  const Vec2 on{0.4, 0.5};   // on the line in real numbers, not in binary
  const Sign s = orient2d(a, b, on);
  CHECK(ray_crossing(a, b, on) ==
        (s == Sign::Zero ? RayCrossing::OnEdge : s == Sign::Positive ? RayCrossing::Crosses : RayCrossing::Misses));
  const Vec2 left{std::nextafter(0.4, 0.0), 0.5};
  CHECK(orient2d(a, b, left) == Sign::Positive);
  CHECK(ray_crossing(a, b, left) == RayCrossing::Crosses);
}
