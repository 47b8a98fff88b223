// Adaptive exact geometric predicates (orient2d, incircle, orient3d): a
// floating-point filter with a forward error bound, then exact expansion
// arithmetic (Shewchuk 1997) only when the filter cannot decide the sign.
#pragma once

#include <cmath>
#include <cstdint>

#include "base/vec.h"

namespace sm {

enum class Sign : std::int8_t { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<std::int8_t>(s)); }

/// Counts of predicate calls and of calls the filter could not decide (those
/// went to exact arithmetic). Passed explicitly: there is no global counter.
struct PredicateStats {
  std::uint64_t orient2d_calls = 0, orient2d_exact = 0;
  std::uint64_t incircle_calls = 0, incircle_exact = 0;
  std::uint64_t orient3d_calls = 0, orient3d_exact = 0;
};

namespace detail {

// Error-bound coefficients of the first (floating-point) stage, from the
// rounding analysis of Shewchuk's predicates; eps = 2^-53.
constexpr double kEps = 1.1102230246251565e-16;
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;
constexpr double kIncircleBound = (10.0 + 96.0 * kEps) * kEps;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;
// Absolute floor added to every bound: the relative analysis above ignores
// underflow, whose absolute error (a few 2^-1074) stays far below 2^-1000.
// Tiny inputs therefore take the exact path, which rescales them first.
constexpr double kAbsFloor = 0x1p-1000;

Sign orient2d_exact(Vec2 a, Vec2 b, Vec2 c);
Sign incircle_exact(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
Sign orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

inline Sign sign_of(double v) { return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero); }

}  // namespace detail

/// Sign of det [a-c; b-c]: Positive when a, b, c turn counter-clockwise,
/// Zero when they are collinear. Exact for every finite input.
inline Sign orient2d(Vec2 a, Vec2 b, Vec2 c, PredicateStats* st = nullptr) {
  const double l = (a.x - c.x) * (b.y - c.y);
  const double r = (a.y - c.y) * (b.x - c.x);
  const double det = l - r;
  const double bound = detail::kOrient2dBound * (std::fabs(l) + std::fabs(r)) + detail::kAbsFloor;
  if (st) ++st->orient2d_calls;
  // bound > 0, so each test settles the sign: one compare per outcome, no
  // second branch on det's sign.
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  if (st) ++st->orient2d_exact;
  return detail::orient2d_exact(a, b, c);
}

/// Positive when d lies strictly inside the circle through a, b, c (which
/// turn counter-clockwise), Zero when the four points are cocircular.
inline Sign incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d, PredicateStats* st = nullptr) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double bound = detail::kIncircleBound * permanent + detail::kAbsFloor;
  if (st) ++st->incircle_calls;
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  if (st) ++st->incircle_exact;
  return detail::incircle_exact(a, b, c, d);
}

/// Sign of det [a-d; b-d; c-d]: Positive when d lies below the plane through
/// a, b, c, seen counter-clockwise from above (Shewchuk's convention).
inline Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d, PredicateStats* st = nullptr) {
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  const double bound = detail::kOrient3dBound * permanent + detail::kAbsFloor;
  if (st) ++st->orient3d_calls;
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  if (st) ++st->orient3d_exact;
  return detail::orient3d_exact(a, b, c, d);
}

}  // namespace sm
