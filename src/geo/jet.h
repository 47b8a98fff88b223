// A point with its first and second derivatives with respect to one parameter: what every
// curve evaluation returns, in the parametric plane (Vec2) or in space (Vec3).
#pragma once

#include "base/vec.h"

namespace sm::geo {

template <class P>
struct Jet {
  P p{}, d1{}, d2{};
};

using Jet2 = Jet<Vec2>;
using Jet3 = Jet<Vec3>;

}  // namespace sm::geo

namespace sm::geo {

/// Gmsh's uniform split of the curve parameter t in [0,1] into n pieces: piece i covers
/// [i/n, (i+1)/n] and local = (t - i/n) / (1/n), computed as Gmsh does so that the same t
/// gives the same point. Out-of-range t extrapolates the first or last piece. O(1).
struct UniformSpan {
  int i = 0;
  double local = 0;
};

inline UniformSpan uniform_span(double t, int n) {
  const double x = t * static_cast<double>(n);
  // Compare in double before converting: a huge or NaN t must not overflow the int.
  int i = 0;
  if (x >= static_cast<double>(n)) i = n - 1;
  else if (x >= 0) i = static_cast<int>(x);
  const double t1 = static_cast<double>(i) / static_cast<double>(n);
  const double t2 = static_cast<double>(i + 1) / static_cast<double>(n);
  return {i, (t - t1) / (t2 - t1)};
}

}  // namespace sm::geo
