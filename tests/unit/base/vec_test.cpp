#include <doctest/doctest.h>

#include "base/id.h"
#include "base/vec.h"

using namespace sm;

TEST_CASE("vec: arithmetic, dot and cross") {
  const Vec2 a{1, 2}, b{3, -1};
  CHECK(dot(a, b) == doctest::Approx(1));
  CHECK(cross(a, b) == doctest::Approx(-7));
  CHECK(norm(Vec2{3, 4}) == doctest::Approx(5));
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  CHECK(cross(x, y) == Vec3{0, 0, 1});
  CHECK(norm2(x + 2.0 * y) == doctest::Approx(5));
}

TEST_CASE("id: default is none, comparison by value") {
  VertexId none;
  CHECK_FALSE(none.valid());
  CHECK(VertexId{3} == VertexId{3});
  CHECK(VertexId{2} < VertexId{3});
}
