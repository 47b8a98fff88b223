// Arc length of a curve in space, integrated piece by piece (Gauss-Legendre): what the 1D
// mesher and tests use to compare sizes on the sphere with sizes in the parameter plane.
#pragma once

#include "geo/curve.h"

namespace sm::geo {

/// Length of the curve between parameters t0 <= t1 (space metric, |dX/dt| integrated with
/// 8-point Gauss-Legendre on each polynomial piece met, subdivided `refine` times).
double curve_length(const Curve& c, double t0 = 0.0, double t1 = 1.0, int refine = 1);

}  // namespace sm::geo
