// Gmsh's BSpline (docs/geometry.md): the clamped B-spline of Gmsh >= 4.0 and the old
// uniform cubic B-spline, both finding the knot span from t in O(1).
#pragma once

#include "geo/jet.h"

#include <span>

namespace sm::geo {

/// Open Euclidean points (Gmsh >= 4.0): clamped B-spline of degree p = min(3, n-1) on the
/// knots {0 x (p+1), 1/(n-p), ..., (n-p-1)/(n-p), 1 x (p+1)}: it interpolates P1 and Pn,
/// and 2/3/4 points give a linear/quadratic/cubic Bezier.
Jet3 eval_bspline_clamped(std::span<const Vec3> pts, double t);
Jet2 eval_bspline_clamped(std::span<const Vec2> pts, double t);
/// Points on a surface geometry (evaluated in (u,v)) and periodic curves (first tag == last
/// tag): the old uniform cubic. Open: end points tripled, n+1 pieces; periodic: n-1 pieces
/// over the distinct points, wrapping around (the curve does not pass through P1).
Jet3 eval_bspline_uniform(std::span<const Vec3> pts, bool periodic, double t);
Jet2 eval_bspline_uniform(std::span<const Vec2> pts, bool periodic, double t);

}  // namespace sm::geo
