// Curve construction (validation, arc frames) and dispatch to the per-kind evaluators.
#include "geo/curve.h"

#include "base/check.h"
#include "geo/curve_bezier.h"
#include "geo/curve_bspline.h"
#include "geo/curve_line.h"
#include "geo/curve_spline.h"

#include <fmt/format.h>

#include <algorithm>

namespace sm::geo {

const char* to_string(CurveKind k) {
  switch (k) {
    case CurveKind::Line: return "Line";
    case CurveKind::Circle: return "Circle";
    case CurveKind::Ellipse: return "Ellipse";
    case CurveKind::Spline: return "Spline";
    case CurveKind::BSpline: return "BSpline";
    case CurveKind::Bezier: return "Bezier";
  }
  return "?";
}

GeoResult<Curve> Curve::make(CurveDef def) {
  const int tag = def.tag;
  const std::size_t n = def.xyz.size();
  const int given = static_cast<int>(n);
  if (def.surface && def.uv.size() != n) return make_error(GeoErrorId::UvCountDiffers, EntityKind::Curve, {tag});
  const char* name = to_string(def.kind);
  switch (def.kind) {
    case CurveKind::Circle:
      if (n != 3)
        return make_error(GeoErrorId::CirclePointCount, EntityKind::Curve, {tag}, {given});
      break;
    case CurveKind::Ellipse:
      if (n != 3 && n != 4)
        return make_error(GeoErrorId::EllipsePointCount, EntityKind::Curve, {tag}, {given});
      break;
    default:
      if (n < 2) return make_error(GeoErrorId::CurvePointCount, EntityKind::Curve, {tag}, {given}, {}, {name});
      break;
  }

  Curve c;
  c.kind_ = def.kind;
  c.periodic_ = def.periodic;
  c.surface_ = def.surface;
  c.xyz_ = std::move(def.xyz);
  c.uv_ = std::move(def.uv);
  if (!c.surface_) c.uv_.clear();
  if (c.kind_ == CurveKind::Circle) {
    auto arc = make_circle_arc(c.xyz_[0], c.xyz_[1], c.xyz_[2], def.plane_normal, tag);
    if (!arc) return arc.error();
    c.circle_ = *arc;
  } else if (c.kind_ == CurveKind::Ellipse) {
    const Vec3 major = c.xyz_.size() == 4 ? c.xyz_[2] : c.xyz_[0];
    auto arc = make_ellipse_arc(c.xyz_[0], c.xyz_[1], major, c.xyz_.back(), def.plane_normal, tag);
    if (!arc) return arc.error();
    c.ellipse_ = *arc;
  } else if (c.kind_ == CurveKind::BSpline) {
    // Gmsh 4 uses clamped knots for open Euclidean B-splines only; periodic ones and those
    // on a surface geometry keep the old uniform definition.
    c.clamped_ = !c.surface_ && !c.periodic_;
  }
  if (c.periodic_ && (c.kind_ == CurveKind::Spline || c.kind_ == CurveKind::BSpline) && n < 3)
    return make_error(GeoErrorId::PeriodicCurvePointCount, EntityKind::Curve, {tag}, {}, {}, {name});
  return c;
}

Jet3 Curve::eval_forward(double t) const {
  switch (kind_) {
    case CurveKind::Circle: return eval_circle_arc(circle_, t);
    case CurveKind::Ellipse: return eval_ellipse_arc(ellipse_, t);
    default: break;
  }
  if (surface_) return surface_->map(eval_uv_forward(t));
  switch (kind_) {
    case CurveKind::Line: return eval_polyline(std::span<const Vec3>(xyz_), t);
    case CurveKind::Spline: return eval_catmull_rom(std::span<const Vec3>(xyz_), periodic_, t);
    case CurveKind::BSpline:
      return clamped_ ? eval_bspline_clamped(std::span<const Vec3>(xyz_), t)
                      : eval_bspline_uniform(std::span<const Vec3>(xyz_), periodic_, t);
    case CurveKind::Bezier: return eval_bezier(std::span<const Vec3>(xyz_), t);
    default: break;
  }
  SM_ASSERT(false, "unhandled curve kind");
}

Jet2 Curve::eval_uv_forward(double t) const {
  SM_ASSERT(surface_.has_value(), "eval_uv on a curve that is not on a surface geometry");
  switch (kind_) {
    case CurveKind::Line: return eval_polyline(std::span<const Vec2>(uv_), t);
    case CurveKind::Spline: return eval_catmull_rom(std::span<const Vec2>(uv_), periodic_, t);
    case CurveKind::BSpline: return eval_bspline_uniform(std::span<const Vec2>(uv_), periodic_, t);
    case CurveKind::Bezier: return eval_bezier(std::span<const Vec2>(uv_), t);
    case CurveKind::Circle:
    case CurveKind::Ellipse: break;
  }
  // An arc is defined in space: pull its jet back through the surface map.
  // uv' = M^-1 J^T X',  uv'' = M^-1 J^T (X'' - Xuu u'^2 - 2 Xuv u'v' - Xvv v'^2).
  const Jet3 x = eval_forward(t);
  Jet2 j;
  j.p = surface_->param(x.p);
  Vec3 xu, xv;
  surface_->tangents(j.p, xu, xv);
  const Metric2 m = surface_->metric(j.p);
  const double det = m.a * m.c - m.b * m.b;
  auto solve = [&](Vec3 rhs3) {
    const double bu = dot(xu, rhs3), bv = dot(xv, rhs3);
    return Vec2{(m.c * bu - m.b * bv) / det, (m.a * bv - m.b * bu) / det};
  };
  j.d1 = solve(x.d1);
  const SecondDerivs s = surface_->second_derivatives(j.p);
  j.d2 = solve(x.d2 - (j.d1.x * j.d1.x) * s.uu - (2.0 * j.d1.x * j.d1.y) * s.uv - (j.d1.y * j.d1.y) * s.vv);
  return j;
}

int Curve::pieces() const {
  const int n = static_cast<int>(xyz_.size());
  switch (kind_) {
    case CurveKind::Line:
    case CurveKind::Spline: return n - 1;
    case CurveKind::BSpline:
      if (clamped_) return n - std::min(3, n - 1);
      return periodic_ ? n - 1 : n + 1;
    default: return 1;
  }
}

Jet3 Curve::eval(double t, bool reversed) const {
  if (!reversed) return eval_forward(t);
  Jet3 j = eval_forward(1.0 - t);
  j.d1 = -j.d1;
  return j;
}

Jet2 Curve::eval_uv(double t, bool reversed) const {
  if (!reversed) return eval_uv_forward(t);
  Jet2 j = eval_uv_forward(1.0 - t);
  j.d1 = -j.d1;
  return j;
}

}  // namespace sm::geo
