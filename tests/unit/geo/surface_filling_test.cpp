// Filling surfaces ("Surface(t) = {loop} <In Sphere{c}>;") against Gmsh 4.8.4: the values
// below were printed by gmsh 4.8.4 (model.getValue(2, tag, [u, v])) on the same script.
#include "geo/model.h"

#include <doctest/doctest.h>

#include <vector>

using namespace sm;
using namespace sm::geo;

namespace {

struct Sample {
  int surface;
  Vec2 uv;
  Vec3 gmsh;
};

}  // namespace

TEST_CASE("filling surfaces: Coons patch on 4 sides, Gmsh's 3-side form, sphere patches") {
  Model m;
  const Vec3 p[] = {{0, 0, 0}, {2, 0, 0.3}, {2.2, 1.5, 0}, {-0.2, 1, 0.5}, {1, -0.3, 0.1}, {2.5, 0.8, 0}, {1, 1.6, 0.2}, {-0.4, 0.5, 0}};
  for (int i = 0; i < 8; ++i) REQUIRE(m.add_point(i + 1, p[i]));
  REQUIRE(m.add_curve(1, CurveKind::Spline, {1, 5, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Spline, {2, 6, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Spline, {3, 7, 4}));
  REQUIRE(m.add_curve(4, CurveKind::Spline, {4, 8, 1}));
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}));
  REQUIRE(m.add_surface_filling(1, {1}));
  REQUIRE(m.add_curve_loop(2, {-4, -3, -2, -1}));
  REQUIRE(m.add_surface_filling(2, {2}));
  REQUIRE(m.add_curve(5, CurveKind::Line, {1, 3}));
  REQUIRE(m.add_curve_loop(3, {1, 2, -5}));
  REQUIRE(m.add_surface_filling(3, {3}));
  REQUIRE(m.add_curve_loop(4, {2, -5, 1}));
  REQUIRE(m.add_surface_filling(4, {4}));
  REQUIRE(m.add_point(10, {0, 0, 0}));
  REQUIRE(m.add_point(11, {1, 0, 0}));
  REQUIRE(m.add_point(12, {0, 1, 0}));
  REQUIRE(m.add_point(13, {0, 0, 1}));
  REQUIRE(m.add_curve(10, CurveKind::Circle, {11, 10, 12}));
  REQUIRE(m.add_curve(11, CurveKind::Circle, {12, 10, 13}));
  REQUIRE(m.add_curve(12, CurveKind::Circle, {13, 10, 11}));
  REQUIRE(m.add_curve_loop(5, {10, 11, 12}));
  REQUIRE(m.add_surface_filling(5, {5}, 10));   // In Sphere{10}
  REQUIRE(m.add_curve_loop(6, {10, 11, 12}));
  REQUIRE(m.add_surface_filling(6, {6}));       // detected: circles about one centre

  const std::vector<Sample> samples = {
      {1, {0.3, 0.2}, {0.53936, 0.11096, -0.00432}},
      {1, {0.5, 0.5}, {1.05, 0.675, -0.05}},
      {1, {0.9, 0.7}, {2.15752, 1.08444, -0.01464}},
      {1, {0, 1}, {-0.2, 1, 0.5}},
      {2, {0.3, 0.2}, {0.24496, 0.28536, -0.03392}},
      {2, {0.9, 0.7}, {1.51608, 1.43516, 0.07704}},
      {2, {1, 0}, {-0.2, 1, 0.5}},
      {3, {0.3, 0.2}, {0.6784, 0.23376, 0.00376}},
      {3, {0.5, 0.5}, {1.1, 0.75, 0}},
      {3, {0.9, 0.7}, {2.1384, 1.046, -0.0192}},
      {3, {0, 1}, {4.2, -1, -2.3}},   // v > u: Gmsh extrapolates its sides
      {4, {0.3, 0.2}, {1.71472, 0.01304, 0.14968}},
      {4, {0.5, 0.5}, {1, -0.3, 0.1}},
      {4, {0, 1}, {3.8, -1, -1.2}},
      {5, {0.3, 0.2}, {0.92441409, 0.1812939, 0.335546}},
      {5, {0.5, 0.5}, {0.707106781, 0, 0.707106781}},
      {5, {0.9, 0.7}, {0.1812939, 0.335546, 0.92441409}},
      {5, {0, 1}, {-0.57735027, -0.57735027, -0.57735027}},
      {6, {0.3, 0.2}, {0.92441409, 0.1812939, 0.335546}},
      {6, {0.9, 0.7}, {0.1812939, 0.335546, 0.92441409}},
  };
  for (const Sample& s : samples) {
    CAPTURE(s.surface);
    CAPTURE(s.uv.x);
    CAPTURE(s.uv.y);
    auto x = m.surface_point(s.surface, s.uv);
    REQUIRE(x.ok());
    CHECK(norm(*x - s.gmsh) < 1e-7);
  }
  // The boundary of a filling is its loop.
  auto b = m.boundary({{2, 3}}, false);
  REQUIRE(b);
  CHECK(b->size() == 3);

  CHECK(m.add_surface_filling(7, {1, 2}).error().kind == GeoErrorKind::BadArgument);
  REQUIRE(m.add_point(20, {3, 3, 0}));
  REQUIRE(m.add_curve(20, CurveKind::Line, {3, 20}));
  REQUIRE(m.add_curve(22, CurveKind::Line, {20, 4}));
  REQUIRE(m.add_curve(23, CurveKind::Line, {4, 1}));
  REQUIRE(m.add_curve_loop(9, {1, 2, 20, 22, 23}));
  auto five = m.add_surface_filling(8, {9});
  REQUIRE_FALSE(five);
  CHECK(five.error().tags == std::vector<int>{8, 9});
  CHECK(m.add_surface_filling(9, {1}, 77).error().kind == GeoErrorKind::MissingEntity);
  CHECK(m.surface_point(42, {0, 0}).error().kind == GeoErrorKind::MissingEntity);
}
