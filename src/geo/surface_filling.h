// Gmsh's "Surface(t) = {loop} <In Sphere{c}>;" (formerly Ruled Surface): a transfinite
// (Coons) patch on the 3 or 4 curves of its loop, on (u,v) in [0,1]^2, projected radially
// onto a sphere when the patch is a sphere patch (docs/geometry.md).
#pragma once

#include "geo/curve.h"

#include <optional>
#include <vector>

namespace sm::geo {

/// One boundary curve of the patch, with its orientation in the loop.
struct PatchSide {
  const Curve* curve = nullptr;
  bool reversed = false;
};

/// The patch on 3 or 4 sides (in loop order). With 4 sides C0..C3 and corners S_i (start
/// of side i), c1 = C0(u), c2 = C1(v), c3 = C2(1-u), c4 = C3(1-v):
///   f = (1-u) c4 + u c2 + (1-v) c1 + v c3 - [(1-u)(1-v) S0 + u(1-v) S1 + uv S2 + (1-u)v S3].
/// With 3 sides (Gmsh's default, Geometry.OldRuledSurface = 0):
///   f = (1-u)(C0(u-v) + C2(1-v) - S0) + (u-v)(C1(v) + C0(u) - S1) + v(C2(1-u) + C1(1-u+v) - S2),
/// the triangle being u >= v (beyond it the sides are extrapolated, as in Gmsh). With a
/// sphere centre O the point is moved radially to distance |S0 - O| from O. With 3 sides
/// and Geometry.OldRuledSurface = 1 (`old_style`), Gmsh's old form on the unit square,
/// the side u = 0 collapsed to S0 (Geo/GeoInterpolation.cpp's TRAN_TRI):
///   f = u C1(v) + (1-v) C0(u) + v C2(1-u) - (u(1-v) S1 + uv S2).
struct TransfinitePatch {
  std::vector<PatchSide> sides;
  std::optional<Vec3> sphere_centre;
  bool old_style = false;
  Vec3 point(Vec2 uv) const;
};

}  // namespace sm::geo
