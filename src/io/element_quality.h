// Shape measures of linear elements in 3D, as Gmsh defines them
// (gmsh-reference §7.3): rho = 2 r_in / r_circ, 1 for an equilateral triangle.
#pragma once

#include "base/vec.h"

namespace sm::io {

/// 2 * inradius / circumradius = 16 A^2 / (perimeter * a * b * c); 0 when degenerate.
double triangle_rho(Vec3 a, Vec3 b, Vec3 c);

}  // namespace sm::io
