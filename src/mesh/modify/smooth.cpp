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

// Whether Lawson flips the edge of s (o its twin)
// now: d inside the circle of u, w, c (ids break ties) and the quad convex.
bool lawson_flips(const TriangleStore& m, const PlanarGeometry& g, Side s, Side o) {
  const VertexId u = m.org(s), w = m.dest(s), c = m.apex(s), d = m.apex(o);
  if (g.in_circle_sos(u, w, c, d) != Sign::Positive) return false;
  return g.orient(c, u, d) == Sign::Positive && g.orient(d, w, c) == Sign::Positive;
}

// Per triangle slot, the Lawson pre-test of make_delaunay:
//   bits 0..2  side e's edge flips in the mesh as it was before any flip
//   bits 3..5  side e is a key side queued at the start (kKeyBit << e)
//   kTouched   a flip rewrote the slot: bits 0..2 say nothing any more
//   kNearTouched  a flip rewrote a neighbour: a twin of the slot may have changed
constexpr std::uint8_t kFlipBits = 7, kKeyBit = 8, kTouched = 64, kNearTouched = 128;

// The pre-test of every edge between alive triangles, in parallel chunks of triangles
// (each chunk writes only its own slots: the same bytes for any thread count).
std::vector<std::uint8_t> lawson_pretest(const TriangleStore& m, int threads) {
  std::vector<std::uint8_t> tag(m.num_slots(), 0);
  parallel_for_chunks(threads, m.num_slots(), kSmoothChunk, [&](std::size_t begin, std::size_t end) {
    const PlanarGeometry g{&m.xy};
    for (std::size_t t = begin; t < end; ++t) {
      if (!m.alive(TriId{static_cast<std::uint32_t>(t)})) continue;
      std::uint8_t bits = 0;
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side s = side_of(TriId{static_cast<std::uint32_t>(t)}, e), o = m.twin[s.value];
        if (!o.valid() || s.value > o.value || m.constrained(s)) continue;
        bits |= static_cast<std::uint8_t>(kKeyBit << e);
        if (lawson_flips(m, g, s, o)) bits |= static_cast<std::uint8_t>(1u << e);
      }
      tag[t] = bits;
    }
  });
  return tag;
}

// Lawson flips from the edges queued on q until every edge reached is locally Delaunay.
std::uint64_t flip_from(TriangleStore& m, FlipQueue& q) {
  const PlanarGeometry g{&m.xy};
  std::uint64_t flips = 0;
  while (!q.empty()) {
    const Side s = q.pop();
    const Side o = m.twin[s.value];
    if (!o.valid() || m.constrained(s) || !lawson_flips(m, g, s, o)) continue;
    q.push_outer_edges(m, m.flip(s));  // d -> c; the four outer edges may now be illegal
    ++flips;
  }
  return flips;
}

// The flips of flip_from from a queue holding every key side in increasing order, with
// the answers of lawson_pretest (tag). That queue's bottom part, the key sides not popped
// yet, is the key bits of the sides below `pending`, never stored: q holds only what
// flips push, above it. A key side whose two slots no flip has rewritten takes its answer
// from tag (the same triangles, the same answer); a slot with no flipping side, untouched
// and next to nothing touched, is popped as a whole, as flip_from would pop its sides to
// no effect. So the same flips in the same order as flip_from: the same bytes.
std::uint64_t flip_pretested(TriangleStore& m, std::vector<std::uint8_t>& tag) {
  const PlanarGeometry g{&m.xy};
  FlipQueue q(m.corner.size());
  std::uint32_t pending = static_cast<std::uint32_t>(m.corner.size());
  auto initially_queued = [&](Side k) {
    return k.value < pending && (tag[k.value / 3] & (kKeyBit << (k.value % 3)));
  };
  std::uint64_t flips = 0;
  auto test_and_flip = [&](Side s) {
    const Side o = m.twin[s.value];
    if (!o.valid() || m.constrained(s)) return;
    const TriId ts = tri_of(s), to = tri_of(o);
    const bool known = s.value < o.value && !((tag[ts.value] | tag[to.value]) & kTouched);
    if (!(known ? (tag[ts.value] >> (s.value - 3 * ts.value)) & 1 : lawson_flips(m, g, s, o))) return;
    const Side n = m.flip(s);  // d -> c, in the slots ts and to
    tag[ts.value] |= kTouched;
    tag[to.value] |= kTouched;
    // The triangles beyond the quad's four outer edges: a twin of theirs changed.
    const Side no = m.twin[n.value];
    for (const Side x : {next(n), prev(n), next(no), prev(no)})
      if (const Side y = m.twin[x.value]; y.valid()) tag[tri_of(y).value] |= kNearTouched;
    q.push_outer_edges(m, n, initially_queued);
    ++flips;
  };
  for (;;) {
    if (!q.empty()) {
      test_and_flip(q.pop());
      continue;
    }
    if (pending == 0) break;
    const std::uint32_t s = pending - 1, t = s / 3;
    if (s % 3 == 2 && !(tag[t] & (kFlipBits | kTouched | kNearTouched))) {
      pending -= 3;
      continue;
    }
    pending = s;
    if (tag[t] & (kKeyBit << (s % 3))) test_and_flip(Side{s});
  }
  return flips;
}

}  // namespace

std::uint64_t make_delaunay(TriangleStore& m, int threads) {
  // Serially the pre-test would only add work; with threads it takes the exact in-circle
  // tests and most of the queue's traffic off the serial loop.
  if (threads > 1) {
    std::vector<std::uint8_t> tag = lawson_pretest(m, threads);
    return flip_pretested(m, tag);
  }
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
        if (v < pinned || !m.out_side_ok(VertexId{static_cast<std::uint32_t>(v)})) continue;
        sides.clear();
        // A free vertex is on no hull edge: its fan closes (a corrupt one is left alone).
        // Nor on a constrained edge: each edge at v is the side leaving v in one triangle
        // of the closed fan and the side coming in in the next, and either may hold the
        // flag, so both are looked at.
        bool on_constraint = false;
        const FanEnd fan = for_each_fan_side(m, m.out_side[v], [&](Side s) {
          sides.push_back(s.value);
          on_constraint = on_constraint || m.constrained(s) || m.constrained(prev(s));
        });
        if (fan != FanEnd::Closed || on_constraint) continue;
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
    st.flips += make_delaunay(m, threads);
  }
  return st;
}

}  // namespace sm
