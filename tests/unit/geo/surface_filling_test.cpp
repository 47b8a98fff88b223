// Filling surfaces ("Surface(t) = {loop} <In Sphere{c}>;") against Gmsh 4.8.4: 42 values of
// model.getValue(2, tag, [u, v]) on the same script (tests/data/geo/gmsh_queries/run.sh).
#include "geo/model.h"

#include <doctest/doctest.h>

#include <fstream>
#include <string>
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
  const Vec3 p[] = {{0, 0, 0},      {2, 0, 0.3},   {2.2, 1.5, 0}, {-0.2, 1, 0.5},
                    {1, -0.3, 0.1}, {2.5, 0.8, 0}, {1, 1.6, 0.2}, {-0.4, 0.5, 0}};
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

  // tests/data/geo/gmsh_queries/filling_surfaces.out: "surface u v x y z" from gmsh 4.8.4's
  // model.getValue on filling_surfaces.geo (the same script), %.17g.
  std::ifstream in(std::string(SM_TEST_DATA) + "/geo/gmsh_queries/filling_surfaces.out");
  REQUIRE(in.good());
  std::vector<Sample> samples;
  Sample smp;
  while (in >> smp.surface >> smp.uv.x >> smp.uv.y >> smp.gmsh.x >> smp.gmsh.y >> smp.gmsh.z) samples.push_back(smp);
  REQUIRE(samples.size() == 42);
  for (const Sample& s : samples) {
    CAPTURE(s.surface);
    CAPTURE(s.uv.x);
    CAPTURE(s.uv.y);
    auto x = m.surface_point(s.surface, s.uv);
    REQUIRE(x.ok());
    CHECK(norm(*x - s.gmsh) < 1e-12);
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
