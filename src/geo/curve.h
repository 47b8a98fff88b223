// A model edge's geometry (paper section 2): one of Gmsh's built-in curve kinds on t in
// [0,1], in space or drawn in the (u,v) plane of a surface geometry and mapped to it.
#pragma once

#include "geo/curve_circle.h"
#include "geo/curve_ellipse.h"
#include "geo/error.h"
#include "geo/jet.h"
#include "geo/surface_geometry.h"

#include <optional>
#include <span>
#include <vector>

namespace sm::geo {

enum class CurveKind { Line, Circle, Ellipse, Spline, BSpline, Bezier };

const char* to_string(CurveKind k);

/// Everything a curve is built from. `uv` is used (and must have the size of `xyz`) when
/// `surface` is set: the curve is then defined in (u,v) (Line, Spline, BSpline, Bezier) or,
/// for arcs, in space from `xyz` with (u,v) obtained through the surface's inverse map.
struct CurveDef {
  CurveKind kind = CurveKind::Line;
  int tag = 0;                           // names the curve in errors only
  std::vector<Vec3> xyz;                 // control points in space
  std::vector<Vec2> uv;                  // control points in the surface's (u,v)
  std::optional<SurfaceGeometry> surface;
  bool periodic = false;                 // first control vertex is the last one (same tag)
  std::optional<Vec3> plane_normal;      // Circle/Ellipse "Plane{nx,ny,nz}"
};

/// Evaluation gives the point and its first two derivatives and costs O(1) for every kind
/// except Bezier (O(n^2) in its degree).
class Curve {
 public:
  /// Checks the control points (counts, arcs) and precomputes what evaluation needs.
  static GeoResult<Curve> make(CurveDef def);

  CurveKind kind() const { return kind_; }
  bool periodic() const { return periodic_; }
  bool on_surface() const { return surface_.has_value(); }
  const SurfaceGeometry* surface() const { return surface_ ? &*surface_ : nullptr; }
  /// Whether the Gmsh definition is evaluated in (u,v) (all but arcs on a surface).
  bool defined_in_uv() const { return on_surface() && kind_ != CurveKind::Circle && kind_ != CurveKind::Ellipse; }
  std::span<const Vec3> control_xyz() const { return xyz_; }
  std::span<const Vec2> control_uv() const { return uv_; }

  /// Point, dX/dt and d2X/dt2 at t in [0,1]. `reversed` evaluates Gmsh's -tag curve:
  /// X(1-t), so the first derivative changes sign.
  Jet3 eval(double t, bool reversed = false) const;
  Vec3 point(double t) const { return eval(t).p; }
  /// (u,v), du/dt, d2u/dt2 on the surface; requires on_surface().
  Jet2 eval_uv(double t, bool reversed = false) const;

  /// Number of polynomial pieces, uniform in t: piece i covers [i/n, (i+1)/n]. Integrators
  /// work piece by piece (the curve is smooth inside a piece).
  int pieces() const;

  /// The arc frame of a Circle (nullptr for other kinds).
  const CircleArc* circle() const { return kind_ == CurveKind::Circle ? &circle_ : nullptr; }
  const EllipseArc* ellipse() const { return kind_ == CurveKind::Ellipse ? &ellipse_ : nullptr; }

  Vec3 begin_point() const { return point(0.0); }
  Vec3 end_point() const { return point(1.0); }

 private:
  Curve() = default;
  Jet3 eval_forward(double t) const;
  Jet2 eval_uv_forward(double t) const;

  CurveKind kind_ = CurveKind::Line;
  bool periodic_ = false;
  bool clamped_ = false;   // BSpline: Gmsh 4's clamped knots (Euclidean, open)
  std::vector<Vec3> xyz_;
  std::vector<Vec2> uv_;
  std::optional<SurfaceGeometry> surface_;
  CircleArc circle_;
  EllipseArc ellipse_;
};

}  // namespace sm::geo
