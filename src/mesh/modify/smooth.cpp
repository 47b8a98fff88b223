// Laplacian smoothing and Lawson flips on the flat store.
#include "mesh/modify/smooth.h"

#include <vector>

#include "mesh/geometry.h"

namespace sm {

std::uint64_t make_delaunay(TriangleStore& m) {
  const PlanarGeometry g{&m.xy};
  std::vector<Side> stack;
  std::vector<std::uint8_t> queued(m.corner.size(), 0);
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    const Side o = m.twin[s];
    if (m.alive(tri_of(Side{s})) && o.valid() && s < o.value && !m.constrained(Side{s})) {
      stack.push_back(Side{s});
      queued[s] = 1;
    }
  }
  std::uint64_t flips = 0;
  while (!stack.empty()) {
    const Side s = stack.back();
    stack.pop_back();
    queued[s.value] = 0;
    const Side o = m.twin[s.value];
    if (!o.valid() || m.constrained(s)) continue;
    const VertexId u = m.org(s), w = m.dest(s), c = m.apex(s), d = m.apex(o);
    if (g.in_circle_sos(u, w, c, d) != Sign::Positive) continue;
    if (g.orient(c, u, d) != Sign::Positive || g.orient(d, w, c) != Sign::Positive) continue;
    const Side n = m.flip(s);  // d -> c; the four outer edges may now be illegal
    ++flips;
    const Side outer[4] = {next(n), prev(n), next(m.twin[n.value]), prev(m.twin[n.value])};
    for (Side x : outer) {
      const Side y = m.twin[x.value];
      if (!y.valid() || m.constrained(x)) continue;
      const Side key = x.value < y.value ? x : y;
      if (!queued[key.value]) queued[key.value] = 1, stack.push_back(key);
    }
  }
  return flips;
}

SmoothStats smooth_laplacian(TriangleStore& m, int passes) {
  SmoothStats st;
  std::vector<std::uint8_t> fixed(m.num_vertices(), 0);
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    if (m.constrained(Side{s}) || !m.twin[s].valid()) fixed[m.corner[s].value] = fixed[m.dest(Side{s}).value] = 1;
  }
  for (int pass = 0; pass < passes; ++pass) {
    for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
      const Side s0 = m.out_side[v];
      if (fixed[v] || !s0.valid()) continue;
      Vec2 sum{0, 0};
      int n = 0;
      Side s = s0;
      do {
        sum += m.pos(m.dest(s));
        ++n;
        s = m.twin[prev(s).value];
      } while (s.valid() && s != s0);
      if (!s.valid() || n < 3) continue;
      const Vec2 old = m.xy[v];
      m.xy[v] = sum / n;
      bool ok = true;
      s = s0;
      do {
        ok = orient2d(m.xy[v], m.pos(m.dest(s)), m.pos(m.apex(s))) == Sign::Positive;
        s = m.twin[prev(s).value];
      } while (ok && s != s0);
      if (ok) ++st.moved;
      else m.xy[v] = old, ++st.refused;
    }
    st.flips += make_delaunay(m);
  }
  return st;
}

}  // namespace sm
