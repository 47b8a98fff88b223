// Laplacian smoothing and Lawson flips on the flat store.
#include "mesh/modify/smooth.h"

#include <algorithm>
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
  // Jacobi form: all free vertices move at once to the average of their
  // neighbours from the previous positions, computed in streaming passes over
  // the sides (each neighbour w of v appears once, as the side v -> w). Then
  // every triangle is checked with the exact orient2d; corners of an inverted
  // or flat triangle go back to their old place, until none is left.
  SmoothStats st;
  const std::uint32_t nv = m.num_vertices();
  std::vector<std::uint8_t> fixed(nv, 0);
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    if (m.constrained(Side{s}) || !m.twin[s].valid()) fixed[m.corner[s].value] = fixed[m.dest(Side{s}).value] = 1;
  }
  std::vector<Vec2> sum(nv), old(nv);
  std::vector<std::uint32_t> count(nv);
  for (int pass = 0; pass < passes; ++pass) {
    std::fill(sum.begin(), sum.end(), Vec2{0, 0});
    std::fill(count.begin(), count.end(), 0);
    for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
      if (!m.alive(tri_of(Side{s}))) continue;
      const std::uint32_t v = m.corner[s].value;
      sum[v] += m.pos(m.dest(Side{s}));
      ++count[v];
    }
    old = m.xy;
    for (std::uint32_t v = 0; v < nv; ++v)
      if (!fixed[v] && count[v] >= 3) m.xy[v] = sum[v] / count[v];
    for (bool again = true; again;) {
      again = false;
      for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
        if (!m.alive(TriId{t})) continue;
        const VertexId a = m.vertex(TriId{t}, 0), b = m.vertex(TriId{t}, 1), c = m.vertex(TriId{t}, 2);
        if (orient2d(m.xy[a.value], m.xy[b.value], m.xy[c.value]) == Sign::Positive) continue;
        for (VertexId v : {a, b, c})
          if (!(m.xy[v.value] == old[v.value])) m.xy[v.value] = old[v.value], ++st.refused, again = true;
      }
    }
    for (std::uint32_t v = 0; v < nv; ++v) st.moved += !(m.xy[v] == old[v]);
    st.flips += make_delaunay(m);
  }
  return st;
}

}  // namespace sm
