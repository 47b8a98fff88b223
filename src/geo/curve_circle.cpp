// Circle arcs with Gmsh 4.8.4's construction rules (checked against gmsh's own evaluation).
#include "geo/curve_circle.h"

#include "geo/sphere.h"

#include <fmt/format.h>

#include <cmath>

namespace sm::geo {

Vec3 arc_normal(Vec3 d_start, Vec3 d_end, std::optional<Vec3> plane_normal) {
  const Vec3 n = cross(d_start, d_end);
  if (norm(n) > 1e-12 * norm(d_start) * norm(d_end)) return n / norm(n);
  if (plane_normal && norm(*plane_normal) > 0) return *plane_normal / norm(*plane_normal);
  return {0, 0, 1};
}

GeoResult<CircleArc> make_circle_arc(Vec3 start, Vec3 centre, Vec3 end, std::optional<Vec3> plane_normal,
                                     int tag) {
  const Vec3 d0 = start - centre, d2 = end - centre;
  const double r1 = norm(d0), r2 = norm(d2);
  if (r1 == 0 || r2 == 0)
    return make_error(GeoErrorId::CircleEndAtCentre, EntityKind::Curve, {tag});
  if (std::abs(r1 - r2) > 0.1 * (r1 + r2))
    return make_error(GeoErrorId::NotCocircular, EntityKind::Curve, {tag}, {}, {r1, r2});
  const Vec3 n = arc_normal(d0, d2, plane_normal);
  CircleArc a;
  a.centre = centre;
  a.radius = r1;
  a.x_axis = d0 / r1;
  const Vec3 y = cross(n, a.x_axis);
  if (norm(y) < 1e-12)
    return make_error(GeoErrorId::CirclePlaneUndefined, EntityKind::Curve, {tag});
  a.y_axis = y / norm(y);
  a.angle = std::atan2(dot(d2, a.y_axis), dot(d2, a.x_axis));
  // Collinear points (a half circle about the fallback normal): Gmsh always turns +pi about
  // that normal; rounding in the dot product could otherwise give -pi.
  if (norm(cross(d0, d2)) <= 1e-12 * r1 * r2 && dot(d0, d2) < 0) a.angle = kPi;
  // Start and end in the same direction: Gmsh measures a full turn and rejects the arc as
  // "greater than Pi".
  if (std::abs(a.angle) <= 1e-12)
    return make_error(GeoErrorId::CircleFull, EntityKind::Curve, {tag});
  return a;
}

Jet3 eval_circle_arc(const CircleArc& arc, double t) {
  const double th = arc.angle * t, c = std::cos(th), s = std::sin(th);
  const double ra = arc.radius * arc.angle;
  Jet3 j;
  j.p = arc.centre + arc.radius * (c * arc.x_axis + s * arc.y_axis);
  j.d1 = ra * (-s * arc.x_axis + c * arc.y_axis);
  j.d2 = (ra * arc.angle) * (-c * arc.x_axis - s * arc.y_axis);
  return j;
}

}  // namespace sm::geo
