// Catmull-Rom evaluation (Gmsh's Spline): cubic Hermite pieces with tangents (P[i+1]-P[i-1])/2.
#include "geo/curve_spline.h"

#include "base/check.h"

namespace sm::geo {

namespace {

template <class P>
Jet<P> catmull_rom(std::span<const P> pts, bool periodic, double t) {
  SM_ASSERT(pts.size() >= 2, "a spline needs two points");
  const int last = static_cast<int>(pts.size()) - 1;   // pieces: last
  const UniformSpan s = uniform_span(t, last);
  const int i = s.i;
  const P p1 = pts[i], p2 = pts[i + 1];
  // Neighbours: wrap for a periodic curve (pts[0] == pts[last] is the same vertex), else
  // Gmsh's phantom points.
  P p0, p3;
  if (i > 0) p0 = pts[i - 1];
  else if (periodic && last >= 2) p0 = pts[last - 1];
  else p0 = 2.0 * p1 - p2;
  if (i + 1 < last) p3 = pts[i + 2];
  else if (periodic && last >= 2) p3 = pts[1];
  else p3 = 2.0 * p2 - p1;

  const double u = s.local, u2 = u * u, u3 = u2 * u;
  const double n = static_cast<double>(last);
  // Basis of the tension-1/2 Catmull-Rom matrix and its derivatives in the local parameter.
  const double b0 = -0.5 * u3 + u2 - 0.5 * u, b1 = 1.5 * u3 - 2.5 * u2 + 1.0;
  const double b2 = -1.5 * u3 + 2.0 * u2 + 0.5 * u, b3 = 0.5 * u3 - 0.5 * u2;
  const double d0 = -1.5 * u2 + 2.0 * u - 0.5, d1 = 4.5 * u2 - 5.0 * u;
  const double d2 = -4.5 * u2 + 4.0 * u + 0.5, d3 = 1.5 * u2 - u;
  const double s0 = -3.0 * u + 2.0, s1 = 9.0 * u - 5.0, s2 = -9.0 * u + 4.0, s3 = 3.0 * u - 1.0;
  Jet<P> j;
  j.p = b0 * p0 + b1 * p1 + b2 * p2 + b3 * p3;
  j.d1 = n * (d0 * p0 + d1 * p1 + d2 * p2 + d3 * p3);
  j.d2 = (n * n) * (s0 * p0 + s1 * p1 + s2 * p2 + s3 * p3);
  return j;
}

}  // namespace

Jet3 eval_catmull_rom(std::span<const Vec3> pts, bool periodic, double t) { return catmull_rom(pts, periodic, t); }
Jet2 eval_catmull_rom(std::span<const Vec2> pts, bool periodic, double t) { return catmull_rom(pts, periodic, t); }

}  // namespace sm::geo
