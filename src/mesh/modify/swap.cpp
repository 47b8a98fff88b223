// Quality swaps on the flat store, with an explicit stack of sides.
#include "mesh/modify/swap.h"

#include <algorithm>
#include <vector>

#include "mesh/modify/flip_queue.h"

namespace sm {

double swap_gain(const TriangleStore& m, Side s, PredicateStats* st) {
  const Side o = m.twin[s.value];
  if (!o.valid() || m.constrained(s)) return -1;
  const VertexId a = m.org(s), b = m.dest(s), c = m.apex(s), d = m.apex(o);
  const Vec2 pa = m.pos(a), pb = m.pos(b), pc = m.pos(c), pd = m.pos(d);
  const double before = std::min(rho(pa, pb, pc), rho(pb, pa, pd));
  const double after = std::min(rho(pc, pa, pd), rho(pd, pb, pc));
  if (after <= before) return after - before;
  // Only now the exact test: the new triangles (c, a, d) and (d, b, c).
  if (orient2d(pc, pa, pd, st) != Sign::Positive || orient2d(pd, pb, pc, st) != Sign::Positive) return -1;
  return after - before;
}

SwapStats swap_for_quality(TriangleStore& m, double min_gain, std::uint64_t max_swaps, PredicateStats* st) {
  SwapStats out;
  FlipQueue q(m.corner.size());
  for (auto s = static_cast<std::uint32_t>(m.corner.size()); s-- > 0;)
    if (m.alive(tri_of(Side{s})) && s < m.twin[s].value) q.push_edge(m, Side{s});
  while (!q.empty() && out.swaps < max_swaps) {
    const Side s = q.pop();
    ++out.tested;
    const double g = swap_gain(m, s, st);
    if (!(g > min_gain)) continue;
    q.push_outer_edges(m, m.flip(s));
    ++out.swaps;
  }
  return out;
}

}  // namespace sm
