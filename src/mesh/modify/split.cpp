// Edge split on the flat store: the triangles beside the edge are rewritten
// in place and one new slot is added per side, so no neighbour outside the
// edge's two triangles changes except for its twin link.
#include "mesh/modify/split.h"

namespace sm {

VertexId split_edge(TriangleStore& m, Side s, Vec2 p, bool allow_constrained, PredicateStats* st) {
  // Triangles (a, b, c) and (b, a, d) become (c, a, p), (p, b, c),
  // (d, b, p) and (p, a, d): p joins a, b, c and d.
  if (m.constrained(s) && !allow_constrained) return VertexId{};
  const Side ts = m.twin[s.value];
  const VertexId a = m.org(s), b = m.dest(s), c = m.apex(s);
  const VertexId d = ts.valid() ? m.apex(ts) : VertexId{};
  const Vec2 pa = m.pos(a), pb = m.pos(b);
  if (orient2d(pa, p, m.pos(c), st) != Sign::Positive || orient2d(p, pb, m.pos(c), st) != Sign::Positive)
    return VertexId{};
  if (d.valid() &&
      (orient2d(pb, p, m.pos(d), st) != Sign::Positive || orient2d(p, pa, m.pos(d), st) != Sign::Positive))
    return VertexId{};
  const std::uint8_t fe = m.side_flags[s.value];
  const Side s_bc = next(s), s_ca = prev(s);
  const Side o_bc = m.twin[s_bc.value];
  const std::uint8_t f_bc = m.side_flags[s_bc.value], f_ca = m.side_flags[s_ca.value];
  Side s_ad, s_db, o_db;
  std::uint8_t f_ad = 0, f_db = 0;
  if (d.valid()) {
    s_ad = next(ts), s_db = prev(ts);
    o_db = m.twin[s_db.value];
    f_ad = m.side_flags[s_ad.value], f_db = m.side_flags[s_db.value];
  }
  const VertexId v = m.add_vertex(p);
  // t1 keeps its slot as (c, a, p): sides c->a (kept twin), a->p, p->c.
  const TriId t1 = tri_of(s);
  const std::uint32_t b1 = 3 * t1.value;
  m.will_change_tri(t1);
  if (ts.valid()) m.will_change_tri(tri_of(ts));
  for (const VertexId x : {a, b, c}) m.will_change_vertex(x);
  if (d.valid()) m.will_change_vertex(d);
  const Side o_ca = m.twin[s_ca.value];
  m.corner[b1] = c, m.corner[b1 + 1] = a, m.corner[b1 + 2] = v;
  m.side_flags[b1] = f_ca, m.side_flags[b1 + 1] = fe, m.side_flags[b1 + 2] = 0;
  m.link(Side{b1}, o_ca);
  // t3 = (v, b, c): sides v->b, b->c (old twin of b->c), c->v.
  const TriId t3 = m.add_triangle(v, b, c);
  const std::uint32_t b3 = 3 * t3.value;
  m.side_flags[b3] = fe, m.side_flags[b3 + 1] = f_bc;
  m.link(Side{b3 + 1}, o_bc);
  m.link(Side{b3 + 2}, Side{b1 + 2});
  m.out_side[c.value] = Side{b1};
  m.out_side[a.value] = Side{b1 + 1};
  m.out_side[v.value] = Side{b3};
  m.out_side[b.value] = Side{b3 + 1};
  if (!d.valid()) {
    m.twin[b1 + 1] = Side{};
    m.twin[b3] = Side{};
    return v;
  }
  // t2 keeps its slot as (d, b, v): sides d->b (kept twin), b->v, v->d.
  const TriId t2 = tri_of(ts);
  const std::uint32_t b2 = 3 * t2.value;
  const Side o_ad = m.twin[s_ad.value];
  m.corner[b2] = d, m.corner[b2 + 1] = b, m.corner[b2 + 2] = v;
  m.side_flags[b2] = f_db, m.side_flags[b2 + 1] = fe, m.side_flags[b2 + 2] = 0;
  m.link(Side{b2}, o_db);
  // t4 = (v, a, d): sides v->a, a->d (old twin of a->d), d->v.
  const TriId t4 = m.add_triangle(v, a, d);
  const std::uint32_t b4 = 3 * t4.value;
  m.side_flags[b4] = fe, m.side_flags[b4 + 1] = f_ad;
  m.link(Side{b4 + 1}, o_ad);
  m.link(Side{b4 + 2}, Side{b2 + 2});
  m.link(Side{b4}, Side{b1 + 1});  // v->a with a->v
  m.link(Side{b2 + 1}, Side{b3});  // b->v with v->b
  m.out_side[d.value] = Side{b2};
  return v;
}

}  // namespace sm
