// Gmsh's Ellipse arc {start, centre, major-axis point, end} ({start, centre, end}: the start
// is the major-axis point), matching Gmsh 4.8.4's evaluation.
#pragma once

#include "geo/error.h"
#include "geo/jet.h"

#include <optional>

namespace sm::geo {

struct EllipseArc {
  Vec3 centre, major, minor;       // unit axes
  double a = 0, b = 0;             // semi-axes along major / minor
  double theta0 = 0, sweep = 0;    // X(t) = c + a cos(th) major + b sin(th) minor, th = theta0 + sweep t
};

/// Plane normal start x end (collinear: as for circles); major axis = the major-axis point's
/// direction projected onto that plane; semi-axes a, b solved so that both start and end lie
/// on the ellipse; linear in the eccentric angle, the short way (end points off the start's
/// plane included, as Gmsh).
GeoResult<EllipseArc> make_ellipse_arc(Vec3 start, Vec3 centre, Vec3 major_point, Vec3 end,
                                       std::optional<Vec3> plane_normal, int tag);
Jet3 eval_ellipse_arc(const EllipseArc& arc, double t);

}  // namespace sm::geo
