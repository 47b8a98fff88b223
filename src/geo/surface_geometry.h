// A surface "geometry" of Gmsh's built-in kernel (docs/geometry.md): the map from the
// parametric plane to space that points, curves and plane surfaces are drawn on.
#pragma once

#include "geo/jet.h"
#include "geo/sphere.h"

#include <variant>

namespace sm::geo {

enum class SurfaceKind { PolarSphere, LonLatSphere };

/// A small value (kind, centre, radius): curves and surfaces keep their own copy.
class SurfaceGeometry {
 public:
  explicit SurfaceGeometry(PolarSphere s) : map_(s) {}
  explicit SurfaceGeometry(Sphere s) : map_(s) {}

  SurfaceKind kind() const { return map_.index() == 0 ? SurfaceKind::PolarSphere : SurfaceKind::LonLatSphere; }
  Vec3 centre() const;
  double radius() const;

  Vec3 point(Vec2 uv) const;
  Vec2 param(Vec3 x) const;
  void tangents(Vec2 uv, Vec3& du, Vec3& dv) const;
  SecondDerivs second_derivatives(Vec2 uv) const;
  Metric2 metric(Vec2 uv) const;

  /// A curve (u(t), v(t)) with its derivatives, mapped to space by the chain rule:
  /// X' = Xu u' + Xv v',  X'' = Xuu u'^2 + 2 Xuv u' v' + Xvv v'^2 + Xu u'' + Xv v''.
  Jet3 map(const Jet2& c) const;

  const PolarSphere* polar() const { return std::get_if<PolarSphere>(&map_); }
  const Sphere* lonlat() const { return std::get_if<Sphere>(&map_); }

  friend bool operator==(const SurfaceGeometry& a, const SurfaceGeometry& b);

 private:
  std::variant<PolarSphere, Sphere> map_;
};

}  // namespace sm::geo
