// Polyline evaluation with Gmsh's uniform parametrisation (one piece per 1/(n-1) of t).
#include "geo/curve_line.h"

#include "base/check.h"

namespace sm::geo {

namespace {

template <class P>
Jet<P> polyline(std::span<const P> pts, double t) {
  SM_ASSERT(pts.size() >= 2, "a line needs two points");
  const int n = static_cast<int>(pts.size()) - 1;
  const UniformSpan s = uniform_span(t, n);
  const P a = pts[s.i], b = pts[s.i + 1];
  Jet<P> j;
  j.p = a + s.local * (b - a);
  j.d1 = static_cast<double>(n) * (b - a);
  return j;
}

}  // namespace

Jet3 eval_polyline(std::span<const Vec3> pts, double t) { return polyline(pts, t); }
Jet2 eval_polyline(std::span<const Vec2> pts, double t) { return polyline(pts, t); }

}  // namespace sm::geo
