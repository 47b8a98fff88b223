// Piecewise Gauss-Legendre arc length.
#include "geo/curve_length.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sm::geo {

namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (symmetric pairs).
constexpr double kNodes[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kWeights[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

double gauss(const Curve& c, double a, double b) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double s = 0;
  for (int i = 0; i < 4; ++i) {
    s += kWeights[i] * (norm(c.eval(mid - half * kNodes[i]).d1) + norm(c.eval(mid + half * kNodes[i]).d1));
  }
  return s * half;
}

}  // namespace

double curve_length(const Curve& c, double t0, double t1, int refine) {
  if (t1 <= t0) return 0.0;
  if (!(t0 == t0) || !(t1 == t1)) return std::numeric_limits<double>::quiet_NaN();
  const int n = c.pieces();
  // Clamp in double before converting (t far outside [0,1] must not overflow the int).
  const int first = static_cast<int>(std::clamp(std::floor(t0 * n), 0.0, static_cast<double>(n - 1)));
  const int last = static_cast<int>(std::clamp(std::ceil(t1 * n), 1.0, static_cast<double>(n)));
  const int sub = std::max(1, refine);
  double total = 0;
  for (int i = first; i < last; ++i) {
    const double a = std::max(t0, static_cast<double>(i) / n), b = std::min(t1, static_cast<double>(i + 1) / n);
    if (b <= a) continue;
    for (int k = 0; k < sub; ++k) total += gauss(c, a + (b - a) * k / sub, a + (b - a) * (k + 1) / sub);
  }
  return total;
}

}  // namespace sm::geo
