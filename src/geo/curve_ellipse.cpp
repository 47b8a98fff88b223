// Ellipse arcs with Gmsh 4.8.4's construction (checked against gmsh's own evaluation).
#include "geo/curve_ellipse.h"

#include "geo/curve_circle.h"
#include "geo/sphere.h"

#include <fmt/format.h>

#include <cmath>

namespace sm::geo {

GeoResult<EllipseArc> make_ellipse_arc(Vec3 start, Vec3 centre, Vec3 major_point, Vec3 end,
                                       std::optional<Vec3> plane_normal, int tag) {
  const Vec3 d0 = start - centre, d2 = end - centre, dm = major_point - centre;
  auto degenerate = [tag](GeoErrorId why) { return make_error(why, EntityKind::Curve, {tag}); };
  if (norm(d0) == 0 || norm(d2) == 0 || norm(dm) == 0) return degenerate(GeoErrorId::EllipseCentrePoint);
  const Vec3 n = arc_normal(d0, d2, plane_normal);
  const Vec3 mp = dm - dot(dm, n) * n;
  if (norm(mp) < 1e-12 * norm(dm)) return degenerate(GeoErrorId::EllipseAxisNormal);
  EllipseArc e;
  e.centre = centre;
  e.major = mp / norm(mp);
  e.minor = cross(n, e.major);
  const double x0 = dot(d0, e.major), y0 = dot(d0, e.minor);
  const double x2 = dot(d2, e.major), y2 = dot(d2, e.minor);
  // x^2 A + y^2 B = 1 at both points, A = 1/a^2, B = 1/b^2.
  const double det = x0 * x0 * y2 * y2 - y0 * y0 * x2 * x2;
  const double scale = norm2(d0) * norm2(d2);
  if (std::abs(det) <= 1e-14 * scale) {
    // Both points symmetric about an axis (or one on it and the other too): the start's
    // axis distance is a semi-axis and the other is undetermined unless one lies on it.
    if (std::abs(y0) <= 1e-14 * norm(d0) && std::abs(y2) <= 1e-14 * norm(d2))
      return degenerate(GeoErrorId::EllipseEndsOnAxis);
    return degenerate(GeoErrorId::EllipseAxesUndetermined);
  }
  const double ia = (y2 * y2 - y0 * y0) / det, ib = (x0 * x0 - x2 * x2) / det;
  if (!(ia > 0) || !(ib > 0)) return degenerate(GeoErrorId::EllipseNoFit);
  e.a = 1.0 / std::sqrt(ia);
  e.b = 1.0 / std::sqrt(ib);
  e.theta0 = std::atan2(y0 / e.b, x0 / e.a);
  double sweep = std::atan2(y2 / e.b, x2 / e.a) - e.theta0;
  if (sweep > kPi) sweep -= 2 * kPi;
  if (sweep <= -kPi) sweep += 2 * kPi;
  // Collinear start and end: half an ellipse, turning +pi about the fallback normal.
  if (norm(cross(d0, d2)) <= 1e-12 * norm(d0) * norm(d2) && sweep < 0) sweep += 2 * kPi;
  if (std::abs(sweep) <= 1e-12)
    return degenerate(GeoErrorId::EllipseFull);
  e.sweep = sweep;
  return e;
}

Jet3 eval_ellipse_arc(const EllipseArc& e, double t) {
  const double th = e.theta0 + e.sweep * t, c = std::cos(th), s = std::sin(th);
  Jet3 j;
  j.p = e.centre + (e.a * c) * e.major + (e.b * s) * e.minor;
  j.d1 = e.sweep * ((-e.a * s) * e.major + (e.b * c) * e.minor);
  j.d2 = (e.sweep * e.sweep) * ((-e.a * c) * e.major - (e.b * s) * e.minor);
  return j;
}

}  // namespace sm::geo
