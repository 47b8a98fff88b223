// Gmsh's Spline / CatmullRom: tension-1/2 Catmull-Rom interpolation through every point,
// piece i on t in [i/(n-1), (i+1)/(n-1)]; open ends use the phantom points 2P1-P2 and
// 2Pn-Pn-1, a periodic curve (first tag == last tag) wraps around instead.
#pragma once

#include "geo/jet.h"

#include <span>

namespace sm::geo {

Jet3 eval_catmull_rom(std::span<const Vec3> pts, bool periodic, double t);
Jet2 eval_catmull_rom(std::span<const Vec2> pts, bool periodic, double t);

}  // namespace sm::geo
