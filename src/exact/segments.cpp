// Segment contact from the signs of four orient2d.
#include "exact/segments.h"

#include "exact/predicates.h"

namespace sm {

SegmentContact segment_contact(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  const Sign o1 = orient2d(p, q, r), o2 = orient2d(p, q, s);
  const Sign o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  // Both ends of one strictly on one side of the other's line: disjoint.
  if (o1 != Sign::Zero && o1 == o2) return {};
  if (o3 != Sign::Zero && o3 == o4) return {};
  if (o1 == Sign::Zero && o2 == Sign::Zero) {   // collinear: do the extents overlap?
    if (collinear_on_segment(p, q, r) || collinear_on_segment(p, q, s) || collinear_on_segment(r, s, p) ||
        collinear_on_segment(r, s, q))
      return {SegmentContactKind::Overlap, -1};
    return {};
  }
  if (o1 == Sign::Zero) return {SegmentContactKind::Touch, 2};
  if (o2 == Sign::Zero) return {SegmentContactKind::Touch, 3};
  if (o3 == Sign::Zero) return {SegmentContactKind::Touch, 0};
  if (o4 == Sign::Zero) return {SegmentContactKind::Touch, 1};
  return {SegmentContactKind::Cross, -1};
}

}  // namespace sm
