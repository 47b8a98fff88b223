// Planar polygon helpers for rings in lon/lat or PolarSphere (u,v) coordinates; every
// left/right decision goes through the exact mesh predicates.
#pragma once

#include <span>

#include "base/vec.h"
#include "exact/predicates.h"

namespace sm::coast {

/// Orientation of a simple closed polygon (first point not repeated): Positive for
/// counter-clockwise. Decided by orient2d at the lowest-then-leftmost vertex, which is
/// convex; neighbours equal to it are skipped. Zero only for a polygon with no area.
Sign ring_orientation(std::span<const Vec2> pts);

/// Whether p lies strictly inside the closed polygon (crossing number with exact
/// orient2d; a point on the boundary counts as outside).
bool point_in_ring(std::span<const Vec2> pts, Vec2 p);

}  // namespace sm::coast
