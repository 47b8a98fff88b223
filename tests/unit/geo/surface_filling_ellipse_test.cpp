// A 3-sided filling patch on two ellipse arcs from one apex and a line, in Gmsh's old
// form (Geometry.OldRuledSurface = 1, as Gmsh 4.8.4's benchmarks/2d/bad_ruled_example.geo
// sets it; the points written out here): the patch against gmsh 4.8.4's
// model.getValue(2, 8, [u, v]) and an ellipse's parameter against getValue(1, 1, [0.5]).
// The new form gives other points inside (0.0024 off at (0.5, 0.25)).
#include "geo/model.h"

#include <doctest/doctest.h>

using namespace sm;
using namespace sm::geo;

TEST_CASE("filling surfaces: Gmsh's 3-side form on ellipse arcs") {
  Model m;
  m.options().old_ruled_surface = true;  // as the benchmark sets it
  REQUIRE(m.add_point(1, {0, 0.042, 0}));
  REQUIRE(m.add_point(2, {0, 0.072, 0}));
  REQUIRE(m.add_point(3, {0.0308972, 0.042, 0.008279}));
  REQUIRE(m.add_point(4, {0.0315, 0.042, 0.0037}));
  REQUIRE(m.add_point(6, {0.0278075, 0.042, 0.00745098}));
  REQUIRE(m.add_point(7, {0.02835, 0.042, 0.00333}));
  REQUIRE(m.add_curve(1, CurveKind::Ellipse, {2, 1, 6, 3}));
  REQUIRE(m.add_curve(2, CurveKind::Ellipse, {2, 1, 7, 4}));
  REQUIRE(m.add_curve(4, CurveKind::Line, {3, 4}));
  REQUIRE(m.add_curve_loop(6, {1, 4, -2}));
  REQUIRE(m.add_surface_filling(8, {6}));
  const Vec3 mid = m.curve(1)->shape->point(0.5);
  CHECK(norm(mid - Vec3{0.02184762, 0.0632132, 0.00585414}) < 1e-7);
  struct {
    Vec2 uv;
    Vec3 x;
  } const samples[] = {{{0.5, 0.25}, {0.02195418, 0.0632132, 0.00504468}},
                       {{0.9, 0.1}, {0.03057634, 0.04669303, 0.00772481}},
                       {{0.3, 0.2}, {0.01408177, 0.0687302, 0.00334282}},
                       {{1, 0.5}, {0.0311986, 0.042, 0.0059895}}};
  for (const auto& s : samples) {
    m.options().old_ruled_surface = true;
    const auto p = m.surface_point(8, s.uv);
    REQUIRE(p);
    CHECK_MESSAGE(norm(*p - s.x) < 1e-7, s.uv.x << " " << s.uv.y << ": " << p->x << " " << p->y << " " << p->z);
    m.options().old_ruled_surface = false;
    CHECK(norm(*m.surface_point(8, s.uv) - s.x) > (s.uv.x == 1 ? -1 : 1e-4));  // on side 1 both agree
  }
}
