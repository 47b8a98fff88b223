// Dispatch of the surface geometry maps and the chain rule for curves drawn on them.
#include "geo/surface_geometry.h"

namespace sm::geo {

Vec3 SurfaceGeometry::centre() const {
  return std::visit([](const auto& m) { return m.centre(); }, map_);
}

double SurfaceGeometry::radius() const {
  return std::visit([](const auto& m) { return m.radius(); }, map_);
}

Vec3 SurfaceGeometry::point(Vec2 uv) const {
  return std::visit([uv](const auto& m) { return m.point(uv); }, map_);
}

Vec2 SurfaceGeometry::param(Vec3 x) const {
  return std::visit([x](const auto& m) { return m.param(x); }, map_);
}

void SurfaceGeometry::tangents(Vec2 uv, Vec3& du, Vec3& dv) const {
  std::visit([&](const auto& m) { m.tangents(uv, du, dv); }, map_);
}

SecondDerivs SurfaceGeometry::second_derivatives(Vec2 uv) const {
  return std::visit([uv](const auto& m) { return m.second_derivatives(uv); }, map_);
}

Metric2 SurfaceGeometry::metric(Vec2 uv) const {
  return std::visit([uv](const auto& m) { return m.metric(uv); }, map_);
}

Jet3 SurfaceGeometry::map(const Jet2& c) const {
  if (const PolarSphere* p = polar()) return p->map(c);
  Jet3 out;
  out.p = point(c.p);
  Vec3 xu, xv;
  tangents(c.p, xu, xv);
  const SecondDerivs s = second_derivatives(c.p);
  out.d1 = c.d1.x * xu + c.d1.y * xv;
  out.d2 = (c.d1.x * c.d1.x) * s.uu + (2.0 * c.d1.x * c.d1.y) * s.uv + (c.d1.y * c.d1.y) * s.vv +
           c.d2.x * xu + c.d2.y * xv;
  return out;
}

bool operator==(const SurfaceGeometry& a, const SurfaceGeometry& b) {
  return a.kind() == b.kind() && a.centre() == b.centre() && a.radius() == b.radius();
}

}  // namespace sm::geo
