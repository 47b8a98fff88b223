// How two closed segments of the plane meet, decided by four exact orient2d: the one
// segment-intersection test for the coast repair, the strait bridges and the spline hulls.
#pragma once

#include <algorithm>
#include <cstdint>

#include "base/vec.h"

namespace sm {

enum class SegmentContactKind : std::uint8_t {
  None,      // disjoint
  Cross,     // the interiors cross at one point
  Touch,     // an end of one lies on the other, the two not collinear
  Overlap,   // collinear and sharing at least one point
};

/// The contact of closed segments pq and rs. For Touch, `end` names the end lying on the
/// other segment: 0 p, 1 q, 2 r, 3 s; of several, the first of r, s, p, q.
struct SegmentContact {
  SegmentContactKind kind = SegmentContactKind::None;
  int end = -1;
};

/// Exact for every finite input. A zero-length segment meets the other only where its
/// point lies on it (the bounding-box test applies to collinear pairs alone).
SegmentContact segment_contact(Vec2 p, Vec2 q, Vec2 r, Vec2 s);

/// Whether closed segments pq and rs share a point.
inline bool segments_meet(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  return segment_contact(p, q, r, s).kind != SegmentContactKind::None;
}

/// Whether x, known to be collinear with a and b, lies on the closed segment ab (within
/// its bounding box: exact, no arithmetic).
inline bool collinear_on_segment(Vec2 a, Vec2 b, Vec2 x) {
  return std::min(a.x, b.x) <= x.x && x.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= x.y &&
         x.y <= std::max(a.y, b.y);
}

}  // namespace sm
