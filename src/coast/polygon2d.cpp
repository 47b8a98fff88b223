// Planar polygon helpers with exact predicates.
#include "coast/polygon2d.h"

namespace sm::coast {

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

bool point_in_ring(std::span<const Vec2> pts, Vec2 p) {
  const std::size_t n = pts.size();
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = pts[j], b = pts[i];
    // Half-open rule on y: the edge counts when it straddles the horizontal line at p.
    const bool up = a.y <= p.y && b.y > p.y;
    const bool down = b.y <= p.y && a.y > p.y;
    if (!up && !down) continue;
    const Sign s = orient2d(a, b, p);
    if (s == Sign::Zero) return false;            // on the boundary
    if ((up && s == Sign::Positive) || (down && s == Sign::Negative)) inside = !inside;
  }
  return inside;
}

}  // namespace sm::coast
