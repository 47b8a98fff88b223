// Gmsh's Line: a segment, or a polyline for more than two points whose piece i covers
// t in [i/(n-1), (i+1)/(n-1)] (docs/geometry.md). In (u,v) when drawn on a surface geometry.
#pragma once

#include "geo/jet.h"

#include <span>

namespace sm::geo {

Jet3 eval_polyline(std::span<const Vec3> pts, double t);
Jet2 eval_polyline(std::span<const Vec2> pts, double t);

}  // namespace sm::geo
