// A ring's mean width: the pass round the ring, and the O(1) estimate from the rope's sums
// with a bound on how far the two can differ (mean_width.h).
#include "coast/mean_width.h"

#include <cmath>
#include <limits>

namespace sm::coast {

double ring_mean_width_m(const KeptRopes& ropes, KeptRopes::Rope r, double radius) {
  // The three sums take their terms in the order of the polygon's own passes (point i,
  // then segment i -> i + 1, the closing segment last): passage closing's decisions and
  // logged widths were made from these doubles.
  Vec2 mean{0, 0}, first{0, 0}, last{0, 0};
  double per = 0, area2 = 0;
  std::size_t n = 0;
  ropes.for_each(r, [&](KeptRopes::TreeNode t) {
    const Vec2 x = ropes.uv(t);
    mean = mean + x;
    if (n == 0) {
      first = x;
    } else {
      per += norm(x - last);
      area2 += cross(last, x);
    }
    last = x;
    ++n;
  });
  if (n == 0) return 0.0;
  per += norm(first - last);
  area2 += cross(last, first);
  mean = (1.0 / static_cast<double>(n)) * mean;
  return per > 0 ? 2.0 * std::abs(0.5 * area2) / per * lambda_m(mean, radius) : 0.0;
}

// The bounds. u is the unit roundoff, n the ring's points, N the largest norm2 of any point
// (KeptRopes::max_norm2), Rm = sqrt(N). A sum of n terms whose every term goes through at
// most h additions is within gamma_h = h u / (1 - h u) of sum|term| of the exact sum: the
// ring's running sums have h <= n, the rope's h <= 3 depth + 3 <= 3 n + 3 (at most three
// additions per level of the tree in KeptRopes::pull: the two links and the part after;
// and the closing segment), so the two orders differ by at most 1.01 (4 n + 3) u sum|term|
// once n u <= 1/400; G = (5 n + 16) u covers that and a few u of each term. The terms:
// - the perimeter: the ring takes norm (hypot, within an ulp), the rope sqrt(norm2) (within
//   1.5 u more): 3 u of each term; the terms are positive, so sum|term| ~ P and
//   eP = 1.02 G P (G covers the 3 u).
// - twice the area: cross(p, q) = cross(p, q - p), so |term| <= Rm |q - p| plus its
//   rounding (2 u of |p.x q.y| + |p.y q.x| <= |p| |q| <= N): sum|term| <= 1.01 Rm (P + eP)
//   + 3 n u N =: SA. The two places may round a term differently (a compiler may fuse one
//   of them into a multiply-add): 6 u N a term. eA = G SA + 6 n u N.
// - the mean point m (the ring's, rounded): within delta = 1.5 (n + 2) u Rm of the true
//   mean c of the points; c is in their hull, so |c| <= Rm, and |c - q| <= D for any point
//   q of the ring with D half its perimeter (two points of a closed curve are at most half
//   its length apart; 1.01 (P + eP) / 2 covers the segments' lengths as rounded).
// Then 2 |A| / P lies in [(|A| - eA) / (P + eP), (|A| + eA) / (P - eP)] and lambda_m =
// 2 R / (1 + |m|^2) in [2 R / (1 + hi^2), 2 R / (1 + lo^2)] for |m| in [lo, hi]; each of
// the ring's last operations rounds by a few u, and so does each bound's: 32 u each side.
MeanWidthBounds bound_ring_mean_width_m(const KeptRopes& ropes, KeptRopes::Rope r, double radius) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const KeptRopes::RingSums s = ropes.ring_sums(r);
  const double n = static_cast<double>(s.points);
  const double u = 0.5 * std::numeric_limits<double>::epsilon();
  const double N = ropes.max_norm2(), Rm = std::sqrt(N) * (1 + 2 * u);
  const double G = (5.0 * n + 16.0) * u;
  const double P = s.uv_perimeter, A = std::abs(s.twice_area);
  if (s.points == 0 || !(n * u <= 1.0 / 400.0)) return {0.0, kInf};
  const double eP = 1.02 * G * P;
  const double SA = 1.01 * Rm * (P + eP) + 3.0 * n * u * N;
  const double eA = G * SA + 6.0 * n * u * N;
  if (!(A > eA) || !(P > eP)) return {0.0, kInf};
  const double delta = 1.5 * (n + 2.0) * u * Rm;
  const double D = 0.505 * (P + eP);
  const double q = norm(s.some_point);
  const double m_lo = std::max(0.0, q * (1 - 2 * u) - D - delta);
  const double m_hi = std::min(Rm, q * (1 + 2 * u) + D) + delta;
  const double lo = (A - eA) / (P + eP) * (2.0 * radius / (1.0 + m_hi * m_hi)) * (1 - 32 * u);
  const double hi = (A + eA) / (P - eP) * (2.0 * radius / (1.0 + m_lo * m_lo)) * (1 + 32 * u);
  if (!(lo >= 0) || !(hi >= lo)) return {0.0, kInf};
  return {lo, hi};
}

std::optional<bool> mean_width_surely_below(const KeptRopes& ropes, KeptRopes::Rope r, double radius,
                                            double width) {
  const MeanWidthBounds b = bound_ring_mean_width_m(ropes, r, radius);
  if (b.hi < width) return true;
  if (b.lo > width) return false;
  return std::nullopt;
}

}  // namespace sm::coast
