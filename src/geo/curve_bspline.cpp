// B-spline evaluation: de Boor's algorithm on the clamped uniform knot vector (with the
// derivative splines for the first and second derivatives), and the uniform cubic basis
// for Gmsh's old B-spline. No allocation, O(1) per call.
#include "geo/curve_bspline.h"

#include "base/check.h"

#include <algorithm>

namespace sm::geo {

namespace {

// Clamped uniform knot vector of n control points and degree p: u_i for i in [0, n+p].
struct ClampedKnots {
  int n, p;
  double knot(int i) const {
    if (i <= p) return 0.0;
    if (i >= n) return 1.0;
    return static_cast<double>(i - p) / static_cast<double>(n - p);
  }
};

// de Boor on the local control points d[0..deg] of span k (u_k <= t < u_k+1) of a spline
// whose knot vector is the clamped one shifted by `shift` (a derivative spline drops the
// first knot per derivative order).
template <class P>
P de_boor(P* d, int deg, int k, int shift, const ClampedKnots& kn, double t) {
  for (int r = 1; r <= deg; ++r)
    for (int j = deg; j >= r; --j) {
      const double lo = kn.knot(j + k - deg + shift), hi = kn.knot(j + 1 + k - r + shift);
      const double a = hi > lo ? (t - lo) / (hi - lo) : 0.0;
      d[j] = (1.0 - a) * d[j - 1] + a * d[j];
    }
  return d[deg];
}

template <class P>
Jet<P> clamped(std::span<const P> pts, double t) {
  SM_ASSERT(pts.size() >= 2, "a B-spline needs two points");
  const int n = static_cast<int>(pts.size());
  const int p = std::min(3, n - 1);
  const ClampedKnots kn{n, p};
  // Span from t directly: the n-p pieces are uniform in t.
  const UniformSpan s = uniform_span(t, n - p);
  const int k = s.i + p;
  P d[4], q[4], r[4];
  for (int j = 0; j <= p; ++j) d[j] = pts[k - p + j];
  // Derivative control points Q_i = p (P_i+1 - P_i) / (u_i+p+1 - u_i+1), degree p-1.
  for (int j = 0; j < p; ++j) {
    const int i = k - p + j;
    q[j] = (static_cast<double>(p) / (kn.knot(i + p + 1) - kn.knot(i + 1))) * (d[j + 1] - d[j]);
  }
  // Second derivative control points from the Q_i (degree p-2).
  for (int j = 0; j + 1 < p; ++j) {
    const int i = k - p + 1 + j;   // index of Q_(j+1) in the derivative spline
    r[j] = (static_cast<double>(p - 1) / (kn.knot(i + p) - kn.knot(i + 1))) * (q[j + 1] - q[j]);
  }
  Jet<P> out;
  if (p >= 2) out.d2 = de_boor(r, p - 2, k - 2, 2, kn, t);
  out.d1 = de_boor(q, p - 1, k - 1, 1, kn, t);
  out.p = de_boor(d, p, k, 0, kn, t);
  return out;
}

template <class P>
Jet<P> uniform(std::span<const P> pts, bool periodic, double t) {
  SM_ASSERT(pts.size() >= 2, "a B-spline needs two points");
  const int n = static_cast<int>(pts.size());
  const int pieces = periodic ? n - 1 : n + 1;
  const UniformSpan s = uniform_span(t, pieces);
  P c[4];
  for (int j = 0; j < 4; ++j) {
    int k;
    if (periodic) {
      k = (s.i - 1 + j) % (n - 1);
      if (k < 0) k += n - 1;
    } else {
      k = std::clamp(s.i - 2 + j, 0, n - 1);
    }
    c[j] = pts[k];
  }
  const double u = s.local, u2 = u * u, u3 = u2 * u, w = 1.0 - u;
  const double m = static_cast<double>(pieces);
  const double b0 = w * w * w / 6.0, b1 = (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0;
  const double b2 = (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0, b3 = u3 / 6.0;
  const double d0 = -0.5 * w * w, d1 = 1.5 * u2 - 2.0 * u, d2 = -1.5 * u2 + u + 0.5, d3 = 0.5 * u2;
  const double s0 = w, s1 = 3.0 * u - 2.0, s2 = -3.0 * u + 1.0, s3 = u;
  Jet<P> out;
  out.p = b0 * c[0] + b1 * c[1] + b2 * c[2] + b3 * c[3];
  out.d1 = m * (d0 * c[0] + d1 * c[1] + d2 * c[2] + d3 * c[3]);
  out.d2 = (m * m) * (s0 * c[0] + s1 * c[1] + s2 * c[2] + s3 * c[3]);
  return out;
}

}  // namespace

Jet3 eval_bspline_clamped(std::span<const Vec3> pts, double t) { return clamped(pts, t); }
Jet2 eval_bspline_clamped(std::span<const Vec2> pts, double t) { return clamped(pts, t); }
Jet3 eval_bspline_uniform(std::span<const Vec3> pts, bool periodic, double t) { return uniform(pts, periodic, t); }
Jet2 eval_bspline_uniform(std::span<const Vec2> pts, bool periodic, double t) { return uniform(pts, periodic, t); }

}  // namespace sm::geo
