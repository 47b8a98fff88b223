// Edge collapse on the flat store: checks (boundary, link condition, exact
// orientation of the ball) and the collapse itself, plus vertex compaction.
#include "mesh/modify/collapse.h"

#include <algorithm>
#include <cstddef>

namespace sm {

FanEnd vertex_ring(const TriangleStore& m, VertexId v, std::vector<Side>& out) {
  out.clear();
  const Side start = m.out_side[v.value];
  if (!start.valid()) return FanEnd::Open;
  const FanEnd end = for_each_fan_side(m, start, [&out](Side s) { out.push_back(s); });
  if (end == FanEnd::Corrupt) out.clear();
  if (end != FanEnd::Open) return end;
  // The walk met start up to the hull counter-clockwise (the last of those has no twin
  // after it), then the sides before start clockwise, nearest first: those come first,
  // reversed, so the ring starts at the clockwise-most side.
  std::size_t last = 0;
  while (last + 1 < out.size() && m.twin[prev(out[last]).value].valid()) ++last;
  std::reverse(out.begin() + static_cast<std::ptrdiff_t>(last) + 1, out.end());
  std::rotate(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(last) + 1, out.end());
  return FanEnd::Open;
}

CollapseCheck can_collapse(const TriangleStore& m, Side s, std::vector<Side>& ring, PredicateStats* st) {
  const VertexId v = m.org(s), w = m.dest(s);
  const FanEnd fan = vertex_ring(m, v, ring);
  if (fan == FanEnd::Corrupt) return CollapseCheck::CorruptFan;
  if (fan != FanEnd::Closed) return CollapseCheck::Constrained;
  for (Side x : ring)
    if (m.constrained(x)) return CollapseCheck::Constrained;
  const Side ts = m.twin[s.value];
  const VertexId c = m.apex(s), d = m.apex(ts);
  // Link condition: the neighbours common to v and w are exactly c and d.
  // w's neighbours are found by walking its fan from the side w -> v.
  for (Side x : ring) {
    const VertexId u = m.dest(x);
    if (u == w || u == c || u == d) continue;
    if (m.has_edge(w, u)) return CollapseCheck::Link;
  }
  // Orientation of the ball with v at w's place; the triangles holding the
  // edge (v, w, c) and (w, v, d) vanish.
  const Vec2 pw = m.pos(w);
  for (Side x : ring) {
    const VertexId a = m.dest(x), b = m.apex(x);  // triangle (v, a, b)
    if (a == w || b == w) continue;
    if (orient2d(pw, m.pos(a), m.pos(b), st) != Sign::Positive) return CollapseCheck::Inverted;
  }
  return CollapseCheck::Ok;
}

void collapse_edge(TriangleStore& m, Side s, const std::vector<Side>& ring) {
  //       c               c
  //     /   \             |
  //    v --s-> w   =>     w      triangles (v, w, c) and (w, v, d) die; the
  //     \   /             |      edges v-c and v-d merge with w-c and w-d
  //       d               d
  const VertexId v = m.org(s), w = m.dest(s);
  const Side ts = m.twin[s.value];
  const VertexId c = m.apex(s), d = m.apex(ts);
  // Outer neighbours of the dying triangles: across w->c and c->v in the
  // first, across v->d and d->w in the second.
  const Side wc = next(s), cv = prev(s), vd = next(ts), dw = prev(ts);
  const Side o_wc = m.twin[wc.value], o_cv = m.twin[cv.value];
  const Side o_vd = m.twin[vd.value], o_dw = m.twin[dw.value];
  const std::uint8_t f_c = m.side_flags[wc.value] | m.side_flags[cv.value];
  const std::uint8_t f_d = m.side_flags[vd.value] | m.side_flags[dw.value];
  for (Side x : ring) {
    const TriId t = tri_of(x);
    if (t == tri_of(s) || t == tri_of(ts)) continue;
    m.corner[x.value] = w;
  }
  for (TriId t : {tri_of(s), tri_of(ts)}) {
    for (std::uint32_t e = 0; e < 3; ++e) m.twin[3 * t.value + e] = Side{};
    m.tri_flags[t.value] = kDead;
    m.free_tris.push_back(t);
  }
  // o_cv runs v -> c (now w -> c), o_wc runs c -> w.
  m.link(o_cv, o_wc);
  if (o_cv.valid()) m.side_flags[o_cv.value] = f_c;
  if (o_wc.valid()) m.side_flags[o_wc.value] = f_c;
  // o_vd runs d -> v (now d -> w), o_dw runs w -> d.
  m.link(o_vd, o_dw);
  if (o_vd.valid()) m.side_flags[o_vd.value] = f_d;
  if (o_dw.valid()) m.side_flags[o_dw.value] = f_d;
  // o_cv (w -> c) and o_dw (w -> d) live (v has a closed fan, so o_cv and
  // o_vd exist); o_vd starts at d, next(o_cv) leaves c.
  m.out_side[v.value] = Side{};
  m.out_side[w.value] = o_cv;
  m.out_side[c.value] = next(o_cv);
  m.out_side[d.value] = o_vd;
}

std::vector<std::uint32_t> drop_isolated_vertices(TriangleStore& m, std::uint32_t first) {
  const std::uint32_t nv = m.num_vertices();
  std::vector<std::uint32_t> map(nv, VertexId::kNone);
  std::uint32_t n = 0;
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (v >= first && !m.out_side[v].valid()) continue;
    map[v] = n;
    m.xy[n] = m.xy[v];
    m.out_side[n] = m.out_side[v];
    ++n;
  }
  m.xy.resize(n);
  m.out_side.resize(n);
  if (n != nv)
    for (VertexId& c : m.corner)
      if (c.valid()) c = VertexId{map[c.value]};
  return map;
}

}  // namespace sm
