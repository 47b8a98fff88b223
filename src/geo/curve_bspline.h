// Gmsh's BSpline (gmsh-reference 3, 3.1). Two definitions, chosen by where the points lie:
// - Euclidean points (Gmsh >= 4.0): a clamped B-spline of degree min(3, n-1) on the knot
//   vector {0 x (p+1), 1/(n-p), ..., (n-p-1)/(n-p), 1 x (p+1)}: it interpolates P1 and Pn,
//   and 2/3/4 points give a linear/quadratic/cubic Bezier;
// - points on a surface geometry (and any periodic BSpline, first tag == last tag): the old
//   uniform cubic B-spline, evaluated in (u,v). Open: end points tripled, n+1 pieces;
//   periodic: n-1 pieces over the distinct points, wrapping around.
// Both find the knot span from t in O(1), however many control points.
#pragma once

#include "geo/jet.h"

#include <span>

namespace sm::geo {

Jet3 eval_bspline_clamped(std::span<const Vec3> pts, double t);
Jet2 eval_bspline_clamped(std::span<const Vec2> pts, double t);
Jet3 eval_bspline_uniform(std::span<const Vec3> pts, bool periodic, double t);
Jet2 eval_bspline_uniform(std::span<const Vec2> pts, bool periodic, double t);

}  // namespace sm::geo
