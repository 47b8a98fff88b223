// Arc lengths: exact cases (segment, circle, great circle on a PolarSphere) and convergence.
#include "geo/curve_length.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace sm;
using namespace sm::geo;

TEST_CASE("curve_length: segments, polylines, circles") {
  CurveDef d;
  d.kind = CurveKind::Line;
  d.xyz = {{0, 0, 0}, {3, 4, 0}, {3, 4, 12}};
  const Curve line = *Curve::make(d);
  CHECK(line.pieces() == 2);
  CHECK(curve_length(line) == doctest::Approx(17.0).epsilon(1e-15));
  CHECK(curve_length(line, 0.25, 0.75) == doctest::Approx(2.5 + 6.0).epsilon(1e-15));
  d.kind = CurveKind::Circle;
  d.xyz = {{2, 0, 0}, {0, 0, 0}, {0, 2, 0}};
  const Curve arc = *Curve::make(d);
  CHECK(curve_length(arc) == doctest::Approx(kPi).epsilon(1e-14));
}

TEST_CASE("curve_length: a PolarSphere line through the pole is a great-circle arc") {
  // (u, 0) for u in [-a, a] is the meridian plane y = 0: a great circle through the north pole.
  const PolarSphere ps({0, 0, 0}, kEarthRadius);
  CurveDef d;
  d.kind = CurveKind::Line;
  d.surface = SurfaceGeometry(ps);
  d.uv = {{-0.5, 0}, {0.5, 0}};
  for (Vec2 p : d.uv) d.xyz.push_back(ps.point(p));
  const Curve c = *Curve::make(d);
  const LonLat a = ps.lonlat_from_param(d.uv[0]), b = ps.lonlat_from_param(d.uv[1]);
  const double exact = great_circle_distance(a, b, kEarthRadius);
  CHECK(curve_length(c, 0, 1, 4) == doctest::Approx(exact).epsilon(1e-13));
  // And the length element is lambda |du/dt|.
  const double lam = ps.lambda(c.eval_uv(0.3).p);
  CHECK(norm(c.eval(0.3).d1) == doctest::Approx(lam * norm(c.eval_uv(0.3).d1)).epsilon(1e-14));
}

TEST_CASE("curve_length: B-spline pieces and refinement converge") {
  CurveDef d;
  d.kind = CurveKind::BSpline;
  for (int i = 0; i < 40; ++i) d.xyz.push_back({double(i), std::sin(0.7 * i), 0.1 * i * i});
  const Curve c = *Curve::make(d);
  CHECK(c.pieces() == 37);
  const double l1 = curve_length(c, 0, 1, 1), l4 = curve_length(c, 0, 1, 4);
  CHECK(std::abs(l1 - l4) < 1e-9 * l4);
  // Additivity across a split inside a piece.
  CHECK(curve_length(c, 0, 0.4137, 2) + curve_length(c, 0.4137, 1, 2) ==
        doctest::Approx(curve_length(c, 0, 1, 2)).epsilon(1e-12));
  d.xyz.push_back(d.xyz.front());
  d.periodic = true;
  CHECK(Curve::make(d)->pieces() == 40);
}
