// The squared distance from a point to a segment on the sphere's (x,y,z), as the deviation
// bound measures it (src/coast/deviation.cpp: each source point against the curve's
// samples, each curve sample against the source): the foot at t = clamp(dot(p - a, ab) /
// |ab|^2, 0, 1). Most segments a point is measured against lie before or after its foot
// (a curve span's eight sample segments, of which one or two are beside the point), so
// the division is made only when the foot falls inside; the perf profile of the 3 km
// import had the wait for that division as the largest part of the deviation pass.
#pragma once

#include <algorithm>

#include "base/vec.h"

namespace sm::coast {

/// norm2(p - (a + t * ab)) with t = clamp(dot(p - a, ab) / l2, 0, 1) (0 when l2 is not
/// positive), l2 = norm2(ab): the same double. Where dot(p - a, ab) <= 0 the quotient is
/// at most 0 and t is 0 (an underflow's -0 gives a foot differing from a only in a
/// zero's sign, squared away); where it is >= l2 the quotient is at least l2 / l2 = 1
/// exactly (division is correctly rounded, so monotone) and t is 1. A NaN takes the
/// division, as before.
inline double segment_distance2(const Vec3& p, const Vec3& a, const Vec3& ab, double l2) {
  double t = 0.0;
  if (l2 > 0) {
    const double num = dot(p - a, ab);
    t = num <= 0 ? 0.0 : num >= l2 ? 1.0 : std::clamp(num / l2, 0.0, 1.0);
  }
  return norm2(p - (a + t * ab));
}

/// The formula segment_distance2 stands for, dividing every time (tests/unit/coast's
/// model of it).
inline double segment_distance2_model(const Vec3& p, const Vec3& a, const Vec3& ab, double l2) {
  double t = l2 > 0 ? dot(p - a, ab) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return norm2(p - (a + t * ab));
}

}  // namespace sm::coast
