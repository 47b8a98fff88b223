// Tests of every sphere formula: maps, inverses, conformal factor and metric against
// finite differences, Gmsh's known point, the two stereographic conventions, geodesy.
#include "geo/sphere.h"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

using namespace sm;
using namespace sm::geo;

namespace {

double dist(Vec3 a, Vec3 b) { return norm(a - b); }

template <class Map>
void check_tangents_fd(const Map& m, Vec2 p, double tol) {
  const double h = 1e-6;
  Vec3 du, dv;
  m.tangents(p, du, dv);
  const Vec3 fu = (m.point(p + Vec2{h, 0}) - m.point(p - Vec2{h, 0})) / (2 * h);
  const Vec3 fv = (m.point(p + Vec2{0, h}) - m.point(p - Vec2{0, h})) / (2 * h);
  CHECK(dist(du, fu) < tol);
  CHECK(dist(dv, fv) < tol);
}

template <class Map>
void check_second_fd(const Map& m, Vec2 p, double tol) {
  const double h = 1e-5;
  const SecondDerivs s = m.second_derivatives(p);
  Vec3 dup, dum, dvp, dvm, tmp;
  m.tangents(p + Vec2{h, 0}, dup, tmp);
  m.tangents(p - Vec2{h, 0}, dum, tmp);
  m.tangents(p + Vec2{0, h}, tmp, dvp);
  m.tangents(p - Vec2{0, h}, tmp, dvm);
  Vec3 a, b, c, d;
  m.tangents(p + Vec2{0, h}, a, b);
  m.tangents(p - Vec2{0, h}, c, d);
  CHECK(dist(s.uu, (dup - dum) / (2 * h)) < tol);
  CHECK(dist(s.vv, (dvp - dvm) / (2 * h)) < tol);
  CHECK(dist(s.uv, (a - c) / (2 * h)) < tol);
}

}  // namespace

TEST_CASE("PolarSphere: Gmsh's known point (-0.3,-0.3) on the unit sphere") {
  const PolarSphere s({0, 0, 0}, 1.0);
  const Vec3 x = s.point({-0.3, -0.3});
  CHECK(x.x == doctest::Approx(0.50847).epsilon(1e-5));
  CHECK(x.y == doctest::Approx(0.50847).epsilon(1e-5));
  CHECK(x.z == doctest::Approx(0.69492).epsilon(1e-5));
  // Exact values: 0.6/1.18 and 0.82/1.18.
  CHECK(std::abs(x.x - 0.6 / 1.18) < 1e-15);
  CHECK(std::abs(x.z - 0.82 / 1.18) < 1e-15);
}

TEST_CASE("PolarSphere: poles, equator, round trips, off-centre sphere") {
  const PolarSphere s({1, -2, 3}, 2.5);
  CHECK(dist(s.point({0, 0}), Vec3{1, -2, 5.5}) < 1e-15);
  CHECK(dist(s.point({1, 0}), Vec3{1 - 2.5, -2, 3}) < 1e-15);   // equator = unit circle
  CHECK(dist(s.singular_point(), Vec3{1, -2, 0.5}) < 1e-15);
  for (double u = -3; u <= 3; u += 0.7)
    for (double v = -2.5; v <= 2.5; v += 0.9) {
      const Vec2 p{u, v};
      const Vec3 x = s.point(p);
      CHECK(std::abs(norm(x - s.centre()) - 2.5) < 1e-14);
      const Vec2 q = s.param(x);
      CHECK(norm(q - p) < 1e-13 * (1 + norm2(p)));
      // radial projection: a point off the sphere has the parameter of its direction
      const Vec2 q2 = s.param(s.centre() + 3.0 * (x - s.centre()));
      CHECK(norm(q2 - p) < 1e-13 * (1 + norm2(p)));
      const LonLat ll = s.lonlat_from_param(p);
      CHECK(norm(s.param_from_lonlat(ll) - p) < 1e-12 * (1 + norm2(p)));
      CHECK(dist(s.from_lonlat(ll), x) < 1e-13);
      const LonLat ll2 = s.to_lonlat(x);
      CHECK(ll2.lon == doctest::Approx(ll.lon).epsilon(1e-12));
      CHECK(ll2.lat == doctest::Approx(ll.lat).epsilon(1e-12));
    }
  CHECK(std::isnan(s.param(s.centre()).x));
}

TEST_CASE("PolarSphere: lonlat conventions") {
  const PolarSphere s({0, 0, 0}, 1.0);
  CHECK(norm(s.param_from_lonlat({0, 90})) < 1e-15);
  const Vec2 e = s.param_from_lonlat({0, 0});        // (lon 0, lat 0) = +x axis
  CHECK(std::abs(e.x + 1) < 1e-15);
  CHECK(std::abs(e.y) < 1e-15);
  const Vec2 f = s.param_from_lonlat({90, 0});
  CHECK(std::abs(f.y + 1) < 1e-15);
  CHECK(s.lonlat_from_param({1, 0}).lon == doctest::Approx(180.0));
  CHECK(s.lonlat_from_param({-1, 0}).lon == doctest::Approx(0.0));
  CHECK(s.lonlat_from_param({0, 0}).lat == 90.0);
  CHECK(s.lonlat_from_param({0.4142135623730950, 0}).lat == doctest::Approx(45.0).epsilon(1e-12));
}

TEST_CASE("PolarSphere: lambda, tangents, second derivatives vs finite differences") {
  const PolarSphere s({0.5, 0.25, -1}, 3.0);
  for (Vec2 p : {Vec2{0, 0}, Vec2{0.3, -0.7}, Vec2{-1.2, 0.4}, Vec2{2.5, 1.5}}) {
    check_tangents_fd(s, p, 1e-8);
    check_second_fd(s, p, 1e-6);
    Vec3 du, dv;
    s.tangents(p, du, dv);
    // conformal: orthogonal tangents of equal length lambda
    CHECK(std::abs(norm(du) - s.lambda(p)) < 1e-13);
    CHECK(std::abs(norm(dv) - s.lambda(p)) < 1e-13);
    CHECK(std::abs(dot(du, dv)) < 1e-13);
    // lambda as the ratio of a small 3D step to its parameter step, in a random direction
    const Vec2 dir{0.6, 0.8};
    const double h = 1e-7;
    const double fd = dist(s.point(p + h * dir), s.point(p - h * dir)) / (2 * h);
    CHECK(fd == doctest::Approx(s.lambda(p)).epsilon(1e-7));
    const Metric2 m = s.metric(p);
    CHECK(m.a == doctest::Approx(dot(du, du)));
    CHECK(m.c == doctest::Approx(dot(dv, dv)));
    CHECK(std::abs(dot(s.normal(p), du)) < 1e-13);
  }
}

TEST_CASE("StereoPlane: the paper's convention and its relation to PolarSphere") {
  const double R = 2.0;
  const StereoPlane sp(R);
  const PolarSphere ps({0, 0, 0}, R);
  CHECK(dist(sp.point({0, 0}), Vec3{0, 0, R}) < 1e-15);
  // the equator is the circle of radius 2R
  CHECK(dist(sp.point({2 * R, 0}), Vec3{R, 0, 0}) < 1e-15);
  for (Vec2 xi : {Vec2{0.3, -0.2}, Vec2{-5, 3}, Vec2{7, 1}}) {
    const Vec3 x = sp.point(xi);
    CHECK(std::abs(norm(x) - R) < 1e-13);
    CHECK(norm(sp.param(x) - xi) < 1e-12 * (1 + norm2(xi)));
    // u = 2R x/(R+z) straight from the paper's formula
    CHECK(std::abs(xi.x - 2 * R * x.x / (R + x.z)) < 1e-12 * (1 + norm2(xi)));
    // same point as the PolarSphere at uv = -xi/(2R)
    CHECK(dist(ps.point(sp.to_polar(xi)), x) < 1e-13);
    CHECK(norm(sp.from_polar(sp.to_polar(xi)) - xi) < 1e-14);
    CHECK(sp.lambda(xi) == doctest::Approx(ps.lambda(sp.to_polar(xi)) / (2 * R)));
    check_tangents_fd(sp, xi, 1e-8);
    Vec3 a, b;
    sp.tangents(xi, a, b);
    CHECK(norm(a) == doctest::Approx(sp.lambda(xi)));
  }
}

TEST_CASE("Sphere (lon/lat radians): map, inverse, metric, singular poles") {
  const Sphere s({0, 0, 1}, 2.0);
  CHECK(dist(s.point({0, 0}), Vec3{2, 0, 1}) < 1e-15);
  CHECK(dist(s.point({0, kPi / 2}), Vec3{0, 0, 3}) < 1e-15);
  for (Vec2 p : {Vec2{0.3, -0.2}, Vec2{-2.5, 1.1}, Vec2{3.0, -1.4}}) {
    CHECK(norm(s.param(s.point(p)) - p) < 1e-13);
    check_tangents_fd(s, p, 1e-8);
    check_second_fd(s, p, 1e-6);
    Vec3 a, b;
    s.tangents(p, a, b);
    const Metric2 m = s.metric(p);
    CHECK(m.a == doctest::Approx(dot(a, a)));
    CHECK(std::abs(m.b - dot(a, b)) < 1e-13);
    CHECK(m.c == doctest::Approx(dot(b, b)));
  }
  CHECK(std::abs(s.metric({1.0, kPi / 2}).a) < 1e-15);   // degenerate at the pole
}

TEST_CASE("geodesy: great circle vs GeographicLib, WGS84 distances, geocentric") {
  // Paris - New York on the sphere: the atan2 formula agrees with GeographicLib (f = 0).
  const LonLat paris{2.3522, 48.8566}, ny{-74.0060, 40.7128};
  const double gc = great_circle_distance(paris, ny, kEarthRadius);
  CHECK(gc == doctest::Approx(geodesic_distance_sphere(paris, ny, kEarthRadius)).epsilon(1e-12));
  CHECK(gc == doctest::Approx(5837e3).epsilon(2e-3));
  // One degree of longitude on the equator.
  CHECK(great_circle_distance({0, 0}, {1, 0}, kEarthRadius) == doctest::Approx(kEarthRadius * kDegToRad));
  // WGS84: one degree of latitude at the equator is 110574.4 m, at the pole 111694 m.
  CHECK(geodesic_distance_wgs84({0, 0}, {0, 1}) == doctest::Approx(110574.4).epsilon(1e-6));
  CHECK(geodesic_distance_wgs84({0, 89}, {0, 90}) == doctest::Approx(111693.9).epsilon(1e-6));
  // Equatorial point and round trip with height.
  const Vec3 e = geocentric_wgs84({0, 0});
  CHECK(std::abs(e.x - 6378137.0) < 1e-6);
  double h = 0;
  const LonLat back = geodetic_wgs84(geocentric_wgs84({12.5, -33.25}, 150.0), &h);
  CHECK(back.lon == doctest::Approx(12.5).epsilon(1e-12));
  CHECK(back.lat == doctest::Approx(-33.25).epsilon(1e-12));
  CHECK(h == doctest::Approx(150.0).epsilon(1e-9));
  // Antipodes: exactly half a circumference.
  CHECK(great_circle_distance({10, 20}, {-170, -20}, 1.0) == doctest::Approx(kPi).epsilon(1e-14));
  const LonLat w = lonlat_from_sphere(sphere_from_lonlat({-180, 10}, 1.0));
  CHECK(w.lon == doctest::Approx(180.0));
}

TEST_CASE("PolarSphere::map: the chain rule in one pass equals the generic composition") {
  const PolarSphere s({0.1, -0.2, 0.3}, 1.7);
  const Jet2 c{{0.4, -0.9}, {1.3, 0.2}, {-0.5, 2.0}};
  const Jet3 j = s.map(c);
  Vec3 xu, xv;
  s.tangents(c.p, xu, xv);
  const SecondDerivs d = s.second_derivatives(c.p);
  CHECK(norm(j.p - s.point(c.p)) < 1e-15);
  CHECK(norm(j.d1 - (c.d1.x * xu + c.d1.y * xv)) < 1e-14);
  const Vec3 d2 =
      (c.d1.x * c.d1.x) * d.uu + (2 * c.d1.x * c.d1.y) * d.uv + (c.d1.y * c.d1.y) * d.vv + c.d2.x * xu + c.d2.y * xv;
  CHECK(norm(j.d2 - d2) < 1e-13);
}
