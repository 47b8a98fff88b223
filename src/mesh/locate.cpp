// Point location (locate.h): the fallback scan of a walk that reached its step limit and
// the barycentric weights.
#include "mesh/locate.h"

#include <vector>

namespace sm {

TriId scan_for(const StoreWalker& w, Vec2 p, TriId from) {
  const TriangleStore& m = w.m;
  if (!from.valid() || !m.alive(from)) return TriId{};
  // Breadth first over the sides the walk may cross: each triangle is queued once, so the
  // scan ends after at most the triangle count.
  std::vector<std::uint8_t> seen(m.num_slots(), 0);
  std::vector<std::uint32_t> queue{from.value};
  seen[from.value] = 1;
  StoreWalker look = w;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const std::uint32_t t = queue[i];
    if (walker_contains(look, t, p)) return TriId{t};
    for (std::uint32_t e = 0; e < 3; ++e) {
      const AcrossStep a = look.across(t, e);
      if (a.kind != Across::Enter || seen[a.next]) continue;
      seen[a.next] = 1;
      queue.push_back(a.next);
    }
  }
  return TriId{};
}

std::array<double, 3> barycentric(Vec2 a, Vec2 b, Vec2 c, Vec2 p) {
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  std::array<double, 3> w = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  if (area > 0) {
    w[0] = ((b.x - p.x) * (c.y - p.y) - (b.y - p.y) * (c.x - p.x)) / area;
    w[1] = ((c.x - p.x) * (a.y - p.y) - (c.y - p.y) * (a.x - p.x)) / area;
    w[2] = ((a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x)) / area;
  }
  return w;
}

}  // namespace sm
