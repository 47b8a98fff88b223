// Node distributions of `Transfinite Curve {c} = n Using Progression | Bump | Beta r;`
// with Gmsh 4.8.4's laws (meshGEdge.cpp's F_Transfinite): the node density along the
// curve, integrated and cut into n - 1 equal parts.
#pragma once

#include <vector>

#include "geo/curve.h"
#include "mesh/mesh_constraints.h"

namespace sm {

/// The density of nodes at normalised parameter t in [0, 1] of a curve of length
/// `length` whose speed there is `speed` (|X'(t)|): Gmsh's F_Transfinite integrand.
///  - Progression r: steps a r^i long (a = L (r - 1) / (r^(n-1) - 1)), density 1 / step;
///    reversed: r -> 1 / r.
///  - Bump c: size -a (tL - L/2)^2 + b, c = (size at the ends) / (size in the middle).
///  - Beta c (> 1): 2c / ((1 + c - t)(c - 1 + t) ln((1 + c)/(c - 1))), t -> 1 - t when
///    reversed; the speed does not enter.
///  - coef 1, coef <= 0 or Beta below 1: uniform in arc length.
double transfinite_density(const TransfiniteCurveSpec& spec, double t, double speed, double length);

/// The parameters (first 0, last 1, increasing) of the spec.nodes nodes on `c`: the
/// density integrated (5-point Gauss on a fine grid that also holds a progression's step
/// ends, so a Line gets the law's exact positions) and inverted by bisection.
std::vector<double> transfinite_parameters(const geo::Curve& c, const TransfiniteCurveSpec& spec);

/// The same on a straight segment of length 1 (speed 1): the nodes' abscissae, for tests
/// and for laws on their own.
std::vector<double> transfinite_abscissae(const TransfiniteCurveSpec& spec);

}  // namespace sm
