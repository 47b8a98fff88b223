// Gmsh's Bezier: one Bezier curve of degree n-1 on t in [0,1] (de Casteljau), in (u,v) when
// drawn on a surface geometry.
#pragma once

#include "geo/jet.h"

#include <span>

namespace sm::geo {

/// Degree up to 31 works on the stack; higher degrees (rare: cost O(n^2) anyway) allocate.
Jet3 eval_bezier(std::span<const Vec3> pts, double t);
Jet2 eval_bezier(std::span<const Vec2> pts, double t);

}  // namespace sm::geo
