// Orientation and point-in-ring with exact predicates, including degenerate input.
#include "coast/polygon2d.h"

#include <doctest/doctest.h>

#include <vector>

using namespace sm;
using namespace sm::coast;

TEST_CASE("polygon2d: orientation and inclusion") {
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
