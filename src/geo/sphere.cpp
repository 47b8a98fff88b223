// Sphere parametrisations and geodesy (paper section 2.1; docs/geometry.md).
#include "geo/sphere.h"

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <limits>

namespace sm::geo {

namespace {

// Longitude in (-180, 180]: the range of atan2 mapped to degrees, with -180 folded to 180
// so that both sides of the dateline have one name.
double wrap_lon(double lon_deg) { return lon_deg <= -180.0 ? lon_deg + 360.0 : lon_deg; }

}  // namespace

PolarSphere::PolarSphere(Vec3 centre, double radius) : centre_(centre), radius_(radius) {}

Vec3 PolarSphere::point(Vec2 uv) const {
  const double rho2 = uv.x * uv.x + uv.y * uv.y;
  const double k = radius_ / (1.0 + rho2);
  return centre_ + Vec3{-2.0 * uv.x * k, -2.0 * uv.y * k, (1.0 - rho2) * k};
}

Vec2 PolarSphere::param(Vec3 x) const {
  Vec3 d = x - centre_;
  const double n = norm(d);
  if (n == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  d *= radius_ / n;
  const double den = radius_ + d.z;
  return {-d.x / den, -d.y / den};
}

double PolarSphere::lambda(Vec2 uv) const { return 2.0 * radius_ / (1.0 + uv.x * uv.x + uv.y * uv.y); }

// With g = 1/(1+u^2+v^2): X = o + r(-2u g, -2v g, 2g - 1), g_u = -2u g^2, g_v = -2v g^2.
void PolarSphere::tangents(Vec2 uv, Vec3& du, Vec3& dv) const {
  const double u = uv.x, v = uv.y;
  const double g = 1.0 / (1.0 + u * u + v * v);
  const double gu = -2.0 * u * g * g, gv = -2.0 * v * g * g;
  du = radius_ * Vec3{-2.0 * g - 2.0 * u * gu, -2.0 * v * gu, 2.0 * gu};
  dv = radius_ * Vec3{-2.0 * u * gv, -2.0 * g - 2.0 * v * gv, 2.0 * gv};
}

SecondDerivs PolarSphere::second_derivatives(Vec2 uv) const {
  const double u = uv.x, v = uv.y;
  const double g = 1.0 / (1.0 + u * u + v * v);
  const double g2 = g * g, g3 = g2 * g;
  const double gu = -2.0 * u * g2, gv = -2.0 * v * g2;
  const double guu = -2.0 * g2 + 8.0 * u * u * g3;
  const double guv = 8.0 * u * v * g3;
  const double gvv = -2.0 * g2 + 8.0 * v * v * g3;
  SecondDerivs s;
  s.uu = radius_ * Vec3{-4.0 * gu - 2.0 * u * guu, -2.0 * v * guu, 2.0 * guu};
  s.uv = radius_ * Vec3{-2.0 * gv - 2.0 * u * guv, -2.0 * gu - 2.0 * v * guv, 2.0 * guv};
  s.vv = radius_ * Vec3{-2.0 * u * gvv, -4.0 * gv - 2.0 * v * gvv, 2.0 * gvv};
  return s;
}

Jet3 PolarSphere::map(const Jet2& c) const {
  const double u = c.p.x, v = c.p.y;
  const double g = 1.0 / (1.0 + u * u + v * v);
  const double g2 = g * g, g3 = g2 * g;
  const double gu = -2.0 * u * g2, gv = -2.0 * v * g2;
  const double guu = -2.0 * g2 + 8.0 * u * u * g3, guv = 8.0 * u * v * g3, gvv = -2.0 * g2 + 8.0 * v * v * g3;
  const Vec3 xu{-2.0 * g - 2.0 * u * gu, -2.0 * v * gu, 2.0 * gu};
  const Vec3 xv{-2.0 * u * gv, -2.0 * g - 2.0 * v * gv, 2.0 * gv};
  const Vec3 xuu{-4.0 * gu - 2.0 * u * guu, -2.0 * v * guu, 2.0 * guu};
  const Vec3 xuv{-2.0 * gv - 2.0 * u * guv, -2.0 * gu - 2.0 * v * guv, 2.0 * guv};
  const Vec3 xvv{-2.0 * u * gvv, -4.0 * gv - 2.0 * v * gvv, 2.0 * gvv};
  const double a = c.d1.x, b = c.d1.y;
  Jet3 out;
  out.p = centre_ + radius_ * Vec3{-2.0 * u * g, -2.0 * v * g, 2.0 * g - 1.0};
  out.d1 = radius_ * (a * xu + b * xv);
  out.d2 = radius_ * ((a * a) * xuu + (2.0 * a * b) * xuv + (b * b) * xvv + c.d2.x * xu + c.d2.y * xv);
  return out;
}

Metric2 PolarSphere::metric(Vec2 uv) const {
  const double l = lambda(uv);
  return {l * l, 0.0, l * l};
}

Vec3 PolarSphere::normal(Vec2 uv) const { return (point(uv) - centre_) / radius_; }

Vec3 PolarSphere::from_lonlat(LonLat ll) const {
  return centre_ + sphere_from_lonlat(ll, radius_);
}

LonLat PolarSphere::to_lonlat(Vec3 x) const { return lonlat_from_sphere(x - centre_); }

Vec2 PolarSphere::param_from_lonlat(LonLat ll) const {
  // Closed form (no detour through 3D): u = -cos(lat)cos(lon)/(1+sin(lat)), and the same
  // with sin(lon) for v; cos(lat)/(1+sin(lat)) = tan(pi/4 - lat/2) stays accurate near the
  // north pole and grows without bound towards the south pole (the singular point).
  const double lon = ll.lon * kDegToRad, lat = ll.lat * kDegToRad;
  const double t = std::tan(0.25 * kPi - 0.5 * lat);
  return {-t * std::cos(lon), -t * std::sin(lon)};
}

LonLat PolarSphere::lonlat_from_param(Vec2 uv) const {
  // The map does not depend on o or r in these coordinates: lat = pi/2 - 2 atan(rho),
  // lon = atan2(-v, -u).
  const double rho = std::hypot(uv.x, uv.y);
  const double lat = 0.5 * kPi - 2.0 * std::atan(rho);
  const double lon = rho == 0 ? 0.0 : std::atan2(-uv.y, -uv.x);
  return {wrap_lon(lon * kRadToDeg), lat * kRadToDeg};
}

StereoPlane::StereoPlane(double radius) : radius_(radius) {}

Vec3 StereoPlane::point(Vec2 xi) const {
  const double r2 = 4.0 * radius_ * radius_;
  const double rho2 = xi.x * xi.x + xi.y * xi.y;
  const double k = r2 / (r2 + rho2);
  return {k * xi.x, k * xi.y, radius_ * (r2 - rho2) / (r2 + rho2)};
}

Vec2 StereoPlane::param(Vec3 x) const {
  const double n = norm(x);
  if (n == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  const Vec3 d = x * (radius_ / n);
  const double k = 2.0 * radius_ / (radius_ + d.z);
  return {k * d.x, k * d.y};
}

double StereoPlane::lambda(Vec2 xi) const {
  const double r2 = 4.0 * radius_ * radius_;
  return r2 / (r2 + xi.x * xi.x + xi.y * xi.y);
}

void StereoPlane::tangents(Vec2 xi, Vec3& dxi, Vec3& deta) const {
  // Chain rule through the PolarSphere of the same radius: uv = -xi / (2R).
  const PolarSphere polar({0, 0, 0}, radius_);
  Vec3 du, dv;
  polar.tangents(to_polar(xi), du, dv);
  const double s = -1.0 / (2.0 * radius_);
  dxi = s * du;
  deta = s * dv;
}

Sphere::Sphere(Vec3 centre, double radius) : centre_(centre), radius_(radius) {}

Vec3 Sphere::point(Vec2 p) const {
  const double cl = std::cos(p.y);
  return centre_ + radius_ * Vec3{cl * std::cos(p.x), cl * std::sin(p.x), std::sin(p.y)};
}

Vec2 Sphere::param(Vec3 x) const {
  const Vec3 d = x - centre_;
  return {std::atan2(d.y, d.x), std::atan2(d.z, std::hypot(d.x, d.y))};
}

void Sphere::tangents(Vec2 p, Vec3& dlon, Vec3& dlat) const {
  const double co = std::cos(p.x), so = std::sin(p.x), ca = std::cos(p.y), sa = std::sin(p.y);
  dlon = radius_ * Vec3{-ca * so, ca * co, 0.0};
  dlat = radius_ * Vec3{-sa * co, -sa * so, ca};
}

SecondDerivs Sphere::second_derivatives(Vec2 p) const {
  const double co = std::cos(p.x), so = std::sin(p.x), ca = std::cos(p.y), sa = std::sin(p.y);
  SecondDerivs s;
  s.uu = radius_ * Vec3{-ca * co, -ca * so, 0.0};
  s.uv = radius_ * Vec3{sa * so, -sa * co, 0.0};
  s.vv = radius_ * Vec3{-ca * co, -ca * so, -sa};
  return s;
}

Metric2 Sphere::metric(Vec2 p) const {
  const double ca = std::cos(p.y);
  return {radius_ * radius_ * ca * ca, 0.0, radius_ * radius_};
}

double great_circle_distance(LonLat a, LonLat b, double radius) {
  const Vec3 pa = sphere_from_lonlat(a, 1.0), pb = sphere_from_lonlat(b, 1.0);
  return radius * std::atan2(norm(cross(pa, pb)), dot(pa, pb));
}

double geodesic_distance_wgs84(LonLat a, LonLat b) {
  double s12 = 0;
  GeographicLib::Geodesic::WGS84().Inverse(a.lat, a.lon, b.lat, b.lon, s12);
  return s12;
}

double geodesic_distance_sphere(LonLat a, LonLat b, double radius) {
  const GeographicLib::Geodesic g(radius, 0.0);
  double s12 = 0;
  g.Inverse(a.lat, a.lon, b.lat, b.lon, s12);
  return s12;
}

Vec3 geocentric_wgs84(LonLat ll, double height) {
  Vec3 x;
  GeographicLib::Geocentric::WGS84().Forward(ll.lat, ll.lon, height, x.x, x.y, x.z);
  return x;
}

LonLat geodetic_wgs84(Vec3 ecef, double* height) {
  double lat = 0, lon = 0, h = 0;
  GeographicLib::Geocentric::WGS84().Reverse(ecef.x, ecef.y, ecef.z, lat, lon, h);
  if (height) *height = h;
  return {lon, lat};
}

Vec3 sphere_from_lonlat(LonLat ll, double radius) {
  const double lon = ll.lon * kDegToRad, lat = ll.lat * kDegToRad;
  const double cl = std::cos(lat);
  return radius * Vec3{cl * std::cos(lon), cl * std::sin(lon), std::sin(lat)};
}

LonLat lonlat_from_sphere(Vec3 x) {
  const double lon = std::atan2(x.y, x.x) * kRadToDeg;
  const double lat = std::atan2(x.z, std::hypot(x.x, x.y)) * kRadToDeg;
  return {wrap_lon(lon), lat};
}

}  // namespace sm::geo
