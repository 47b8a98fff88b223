// Gmsh's Circle arc {start, centre, end} (docs/geometry.md) with the construction rules
// measured on Gmsh 4.8.4.
#pragma once

#include "geo/error.h"
#include "geo/jet.h"

#include <optional>

namespace sm::geo {

struct CircleArc {
  Vec3 centre, x_axis, y_axis;   // unit axes: x towards the start point
  double radius = 0, angle = 0;  // X(t) = c + r(cos(angle t) x + sin(angle t) y)
};

/// Radius |start - centre|, plane normal start x end (the short way round, so the angle is
/// at most pi); the optional Plane normal is used only when start, centre and end are
/// collinear (a half circle, always +pi about the normal), and Gmsh's default normal there
/// is +z. Start and end radii differing by more than 10% of their sum is Gmsh's "not
/// cocircular" error. `tag` only names the curve in the error.
GeoResult<CircleArc> make_circle_arc(Vec3 start, Vec3 centre, Vec3 end, std::optional<Vec3> plane_normal,
                                     int tag);
Jet3 eval_circle_arc(const CircleArc& arc, double t);

/// Gmsh's fallback normal for an arc whose points are collinear: the user's Plane normal,
/// else +z. Shared with the ellipse.
Vec3 arc_normal(Vec3 d_start, Vec3 d_end, std::optional<Vec3> plane_normal);

}  // namespace sm::geo
