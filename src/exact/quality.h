// The element quality measures, one definition each for the refiners, the optimiser, the
// recombination, the statistics and the writers: the shape quality of a triangle,
// rho = 2 r_in / r_circ (the paper's aspect ratio; Gmsh's "gamma" of a triangle): 1 for an
// equilateral triangle, 0 for a degenerate one; the mean ratio eta; Gmsh's gamma in the
// plane; the corner quality of a quadrangle. Here beside the predicates because, like
// them, they are plain functions of coordinates that every module meshing or writing
// elements shares (docs/architecture.md); they are floating-point measures, not decisions.
#pragma once

#include <cmath>

#include "base/vec.h"

namespace sm {

/// rho = 2 r_in / r_circ = num / den of a plane triangle, kept apart so that hot loops can
/// compare num against a bound times den without dividing. With r_in = 2A / P and
/// r_circ = la lb lc / (4A): num = 16 A^2 = 4 area2^2 and den = P la lb lc.
struct RhoTerms {
  double area2;   // twice the signed area: > 0 when a, b, c turn counter-clockwise
  double num;
  double den;
};

/// Plain square roots, not std::hypot: the meshadapt and optimiser loops call this
/// millions of times and hypot is several times slower.
inline RhoTerms rho_terms(Vec2 a, Vec2 b, Vec2 c) {
  const double area2 = cross(b - a, c - a);
  const double la = std::sqrt(norm2(b - c)), lb = std::sqrt(norm2(c - a)), lc = std::sqrt(norm2(a - b));
  return {area2, 4 * area2 * area2, (la + lb + lc) * la * lb * lc};
}

/// rho_terms with la = std::sqrt(norm2(b - c)) given (a vertex star's outer edge: the same
/// wherever the optimiser tries its centre a), the same doubles; num and den are left 0
/// unless a, b, c turn counter-clockwise in floating point (then no root is taken).
inline RhoTerms rho_terms_ccw(Vec2 a, Vec2 b, Vec2 c, double la) {
  const double area2 = cross(b - a, c - a);
  if (!(area2 > 0)) return {area2, 0, 0};
  const double lb = std::sqrt(norm2(c - a)), lc = std::sqrt(norm2(a - b));
  return {area2, 4 * area2 * area2, (la + lb + lc) * la * lb * lc};
}

/// rho of a plane triangle of either orientation; 0 when degenerate.
inline double rho(Vec2 a, Vec2 b, Vec2 c) {
  const RhoTerms t = rho_terms(a, b, c);
  return t.den > 0 ? t.num / t.den : 0.0;
}

/// rho of a plane triangle, or -1 unless a, b, c turn counter-clockwise in floating point
/// (a filter: whatever is kept must still pass the exact orient2d).
inline double rho_ccw(Vec2 a, Vec2 b, Vec2 c) {
  const RhoTerms t = rho_terms(a, b, c);
  return t.area2 > 0 ? t.num / t.den : -1.0;
}

/// rho of a triangle in space, with la = norm(b - c) given: the outer edge of a vertex
/// star, the same wherever the optimiser tries its centre a.
inline double rho(Vec3 a, Vec3 b, Vec3 c, double la) {
  const double lb = norm(c - a), lc = norm(a - b);
  const double area2_sq = norm2(cross(b - a, c - a));   // (2A)^2
  const double den = (la + lb + lc) * la * lb * lc;
  return den > 0 ? 4 * area2_sq / den : 0.0;
}

/// rho of a triangle in space (chord lengths, the flat triangle through the three points);
/// 0 when degenerate.
inline double rho(Vec3 a, Vec3 b, Vec3 c) { return rho(a, b, c, norm(b - c)); }

/// Mean ratio 4 sqrt(3) area / (sum of squared edge lengths), in [0, 1].
double eta(Vec2 a, Vec2 b, Vec2 c);

/// 2 sqrt(3) r_in / longest edge, in [0, 1]: the 2D form of Gmsh's "gamma" quality type
/// (volume / sum of faces / longest edge).
double gamma(Vec2 a, Vec2 b, Vec2 c);

/// The corner quality of a quadrangle a b c d in space: 1 - max |90 - corner angle| / 90
/// (1 for a rectangle, 0 when a corner is flat or null).
double quad_quality(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

}  // namespace sm
