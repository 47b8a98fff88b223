// de Casteljau evaluation of a Bezier curve with its first two derivatives: run the
// recursion down to the last three points Q0, Q1, Q2 (degree 2 stage); then
// p = (1-t)^2 Q0 + 2t(1-t) Q1 + t^2 Q2, p' = n((1-t)(Q1-Q0) + t(Q2-Q1)), p'' = n(n-1)(Q2-2Q1+Q0).
#include "geo/curve_bezier.h"

#include "base/check.h"

#include <algorithm>
#include <array>
#include <vector>

namespace sm::geo {

namespace {

template <class P>
Jet<P> bezier(std::span<const P> pts, double t) {
  SM_ASSERT(pts.size() >= 2, "a Bezier curve needs two points");
  const int n = static_cast<int>(pts.size()) - 1;   // degree
  std::array<P, 32> small;
  std::vector<P> large;
  P* q = small.data();
  if (pts.size() > small.size()) {
    large.assign(pts.begin(), pts.end());
    q = large.data();
  } else {
    std::copy(pts.begin(), pts.end(), small.begin());
  }
  const double w = 1.0 - t;
  Jet<P> j;
  if (n == 1) {
    j.p = w * q[0] + t * q[1];
    j.d1 = q[1] - q[0];
    return j;
  }
  // Reduce n+1 points to 3.
  for (int level = n; level > 2; --level)
    for (int i = 0; i < level; ++i) q[i] = w * q[i] + t * q[i + 1];
  const P q0 = q[0], q1 = q[1], q2 = q[2];
  const double dn = static_cast<double>(n);
  j.p = (w * w) * q0 + (2.0 * t * w) * q1 + (t * t) * q2;
  j.d1 = dn * (w * (q1 - q0) + t * (q2 - q1));
  j.d2 = (dn * (dn - 1.0)) * (q2 - 2.0 * q1 + q0);
  return j;
}

}  // namespace

Jet3 eval_bezier(std::span<const Vec3> pts, double t) { return bezier(pts, t); }
Jet2 eval_bezier(std::span<const Vec2> pts, double t) { return bezier(pts, t); }

}  // namespace sm::geo
