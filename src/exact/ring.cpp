// Point location on planar rings with exact predicates.
#include "exact/ring.h"

namespace sm {

Sign ring_orientation(std::span<const Vec2> pts) {
  const std::size_t n = pts.size();
  if (n < 3) return Sign::Zero;
  std::size_t lo = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (pts[i].y < pts[lo].y || (pts[i].y == pts[lo].y && pts[i].x < pts[lo].x)) lo = i;
  std::size_t prev = (lo + n - 1) % n, next = (lo + 1) % n;
  while (prev != lo && pts[prev] == pts[lo]) prev = (prev + n - 1) % n;
  while (next != lo && pts[next] == pts[lo]) next = (next + 1) % n;
  if (prev == lo || next == lo || prev == next) return Sign::Zero;
  return orient2d(pts[prev], pts[lo], pts[next]);
}

RayCrossing ray_crossing(Vec2 a, Vec2 b, Vec2 p) {
  const bool up = a.y <= p.y && b.y > p.y;
  const bool down = b.y <= p.y && a.y > p.y;
  if (!up && !down) return RayCrossing::Misses;
  // The edge straddles the line y = p.y: it crosses the ray when p is on its left going
  // up, on its right going down.
  const Sign s = orient2d(a, b, p);
  if (s == Sign::Zero) return RayCrossing::OnEdge;
  return (up && s == Sign::Positive) || (down && s == Sign::Negative) ? RayCrossing::Crosses : RayCrossing::Misses;
}

bool point_in_ring(std::span<const Vec2> pts, Vec2 p) {
  const std::size_t n = pts.size();
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const RayCrossing c = ray_crossing(pts[j], pts[i], p);
    if (c == RayCrossing::OnEdge) return false;   // on the boundary
    if (c == RayCrossing::Crosses) inside = !inside;
  }
  return inside;
}

}  // namespace sm
