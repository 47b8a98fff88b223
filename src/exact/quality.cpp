// The quality measures of exact/quality.h that are not inline.
#include "exact/quality.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sm {

double eta(Vec2 a, Vec2 b, Vec2 c) {
  const double s = norm2(b - c) + norm2(c - a) + norm2(a - b);
  const double area = 0.5 * std::fabs(cross(b - a, c - a));
  return s > 0 ? 4 * std::sqrt(3.0) * area / s : 0.0;
}

double gamma(Vec2 a, Vec2 b, Vec2 c) {
  const double la = norm(b - c), lb = norm(c - a), lc = norm(a - b);
  const double area = 0.5 * std::fabs(cross(b - a, c - a));
  const double p = la + lb + lc, lmax = std::max({la, lb, lc});
  return p > 0 && lmax > 0 ? 2 * std::sqrt(3.0) * (2 * area / p) / lmax : 0.0;
}

namespace {

// |90 - the corner angle at `at`| in degrees; 90 when an edge is null.
double corner_deviation(Vec3 prev, Vec3 at, Vec3 next) {
  const Vec3 a = prev - at, b = next - at;
  const double na = norm(a), nb = norm(b);
  if (!(na > 0) || !(nb > 0)) return 90.0;
  const double c = std::clamp(dot(a, b) / (na * nb), -1.0, 1.0);
  return std::abs(90.0 - std::acos(c) * 180.0 / std::numbers::pi);
}

}  // namespace

double quad_quality(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double dev = std::max({corner_deviation(d, a, b), corner_deviation(a, b, c), corner_deviation(b, c, d),
                               corner_deviation(c, d, a)});
  return 1.0 - dev / 90.0;
}

}  // namespace sm
