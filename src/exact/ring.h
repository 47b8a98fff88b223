// Point location on planar rings (lon/lat or PolarSphere (u,v) coordinates): orientation,
// the ray crossing of one edge, point-in-ring; every left/right decision is an exact orient2d.
#pragma once

#include <span>

#include "base/vec.h"
#include "exact/predicates.h"

namespace sm {

/// Orientation of a simple closed polygon (first point not repeated): Positive for
/// counter-clockwise. Decided by orient2d at the lowest-then-leftmost vertex, which is
/// convex; neighbours equal to it are skipped. Zero only for a polygon with no area.
Sign ring_orientation(std::span<const Vec2> pts);

/// How the edge a->b meets the ray from p towards +x, with the half-open rule on y (an
/// edge counts when min(a.y, b.y) <= p.y < max(a.y, b.y)), so that a ray through a vertex
/// crosses the ring once: Crosses toggles inside/outside, OnEdge means p lies on a->b.
enum class RayCrossing { Misses, Crosses, OnEdge };
RayCrossing ray_crossing(Vec2 a, Vec2 b, Vec2 p);

/// Whether p lies strictly inside the closed polygon (crossing number with exact
/// orient2d; a point on the boundary counts as outside).
bool point_in_ring(std::span<const Vec2> pts, Vec2 p);

}  // namespace sm
