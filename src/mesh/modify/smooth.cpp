// Laplacian smoothing and Lawson flips on the flat store.
#include "mesh/modify/smooth.h"

#include <algorithm>
#include <vector>

#include "base/parallel.h"
#include "mesh/geometry.h"
#include "mesh/modify/flip_queue.h"

namespace sm {
namespace {
// Vertices (or triangles) per chunk of the parallel loops: fixed, so chunk boundaries
// and results do not depend on the thread count.
constexpr std::size_t kSmoothChunk = 16384;

// Lawson flips from the edges queued on q until every edge reached is locally Delaunay.
std::uint64_t flip_from(TriangleStore& m, FlipQueue& q) {
  const PlanarGeometry g{&m.xy};
  std::uint64_t flips = 0;
  while (!q.empty()) {
    const Side s = q.pop();
    const Side o = m.twin[s.value];
    if (!o.valid() || m.constrained(s)) continue;
    const VertexId u = m.org(s), w = m.dest(s), c = m.apex(s), d = m.apex(o);
    if (g.in_circle_sos(u, w, c, d) != Sign::Positive) continue;
    if (g.orient(c, u, d) != Sign::Positive || g.orient(d, w, c) != Sign::Positive) continue;
    q.push_outer_edges(m, m.flip(s));  // d -> c; the four outer edges may now be illegal
    ++flips;
  }
  return flips;
}

}  // namespace

std::uint64_t make_delaunay(TriangleStore& m) {
  FlipQueue q(m.corner.size());
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.alive(tri_of(Side{s})) && s < m.twin[s].value) q.push_edge(m, Side{s});
  return flip_from(m, q);
}

std::uint64_t make_delaunay_around(TriangleStore& m, std::span<const TriId> tris) {
  FlipQueue q(m.corner.size());
  for (const TriId t : tris) {
    if (!m.alive(t)) continue;
    for (std::uint32_t e = 0; e < 3; ++e) q.push_edge(m, side_of(t, e));
  }
  return flip_from(m, q);
}

SmoothStats smooth_laplacian(TriangleStore& m, int passes, int threads, std::uint32_t pinned) {
  // Jacobi form: all free vertices move at once to the average of their neighbours from
  // the previous positions. Each vertex gathers its own fan (so vertices are independent
  // and split into chunks across threads) and sums its neighbours in increasing side
  // order, the order of a serial sweep over the sides, so the bytes do not depend on the
  // thread count. Then every triangle is checked with the exact orient2d; corners of an
  // inverted or flat triangle go back to their old place, sweeping in triangle order
  // until none is left (the parallel scan only finds where the first sweep must start).
  SmoothStats st;
  const std::uint32_t nv = m.num_vertices();
  std::vector<std::uint8_t> fixed(nv, 0);
  std::fill(fixed.begin(), fixed.begin() + std::min(pinned, nv), std::uint8_t{1});
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    if (m.constrained(Side{s}) || !m.twin[s].valid()) fixed[m.corner[s].value] = fixed[m.dest(Side{s}).value] = 1;
  }
  const std::size_t chunks_v = (nv + kSmoothChunk - 1) / kSmoothChunk;
  const std::size_t chunks_t = (m.num_slots() + kSmoothChunk - 1) / kSmoothChunk;
  std::vector<std::uint64_t> moved(chunks_v);
  std::vector<std::uint32_t> first_bad(chunks_t);
  std::vector<Vec2> old;
  for (int pass = 0; pass < passes; ++pass) {
    old = m.xy;
    parallel_for_chunks(threads, nv, kSmoothChunk, [&](std::size_t begin, std::size_t end) {
      std::vector<std::uint32_t> sides;
      for (std::size_t v = begin; v < end; ++v) {
        if (fixed[v] || !m.out_side_ok(VertexId{static_cast<std::uint32_t>(v)})) continue;
        sides.clear();
        // A free vertex is on no hull edge: its fan closes (a corrupt one is left alone).
        if (for_each_fan_side(m, m.out_side[v], [&sides](Side s) { sides.push_back(s.value); }) != FanEnd::Closed)
          continue;
        if (sides.size() < 3) continue;
        std::sort(sides.begin(), sides.end());
        Vec2 sum{0, 0};
        for (std::uint32_t x : sides) sum += old[m.dest(Side{x}).value];
        m.xy[v] = sum / static_cast<double>(static_cast<std::uint32_t>(sides.size()));
      }
    });
    // Undo sweeps. A triangle acts in a sweep only when it is not counter-clockwise and
    // one of its corners moved; triangles before the first such one do nothing.
    auto acts = [&](std::uint32_t t) {
      if (!m.alive(TriId{t})) return false;
      const VertexId a = m.vertex(TriId{t}, 0), b = m.vertex(TriId{t}, 1), c = m.vertex(TriId{t}, 2);
      if (orient2d(m.xy[a.value], m.xy[b.value], m.xy[c.value]) == Sign::Positive) return false;
      return !(m.xy[a.value] == old[a.value]) || !(m.xy[b.value] == old[b.value]) ||
             !(m.xy[c.value] == old[c.value]);
    };
    for (;;) {
      parallel_for_chunks(threads, m.num_slots(), kSmoothChunk, [&](std::size_t begin, std::size_t end) {
        std::uint32_t f = TriId::kNone;
        for (std::size_t t = begin; t < end && f == TriId::kNone; ++t)
          if (acts(static_cast<std::uint32_t>(t))) f = static_cast<std::uint32_t>(t);
        first_bad[begin / kSmoothChunk] = f;
      });
      const auto it = std::min_element(first_bad.begin(), first_bad.end());
      if (it == first_bad.end() || *it == TriId::kNone) break;
      const std::uint32_t from = *it;
      for (std::uint32_t t = from; t < m.num_slots(); ++t) {
        if (!m.alive(TriId{t})) continue;
        const VertexId a = m.vertex(TriId{t}, 0), b = m.vertex(TriId{t}, 1), c = m.vertex(TriId{t}, 2);
        if (orient2d(m.xy[a.value], m.xy[b.value], m.xy[c.value]) == Sign::Positive) continue;
        for (VertexId v : {a, b, c})
          if (!(m.xy[v.value] == old[v.value])) m.xy[v.value] = old[v.value], ++st.refused;
      }
    }
    parallel_for_chunks(threads, nv, kSmoothChunk, [&](std::size_t begin, std::size_t end) {
      std::uint64_t n = 0;
      for (std::size_t v = begin; v < end; ++v) n += !(m.xy[v] == old[v]);
      moved[begin / kSmoothChunk] = n;
    });
    for (std::uint64_t n : moved) st.moved += n;
    st.flips += make_delaunay(m);
  }
  return st;
}

}  // namespace sm
