// The flat triangulation store: slot management, vertex rotation, flip and
// compaction. Topology only; geometry is asked through mesh/geometry.h.
#include "mesh/triangulation.h"

#include <algorithm>

#include "base/check.h"
#include "mesh/delaunay.h"
#include "mesh/store_undo.h"

namespace sm {

VertexId TriangleStore::add_vertex(Vec2 p) {
  xy.push_back(p);
  out_side.push_back(Side{});
  return VertexId{static_cast<std::uint32_t>(xy.size() - 1)};
}

TriId TriangleStore::add_triangle(VertexId a, VertexId b, VertexId c) {
  TriId t;
  if (!free_tris.empty()) {
    t = free_tris.back();
    free_tris.pop_back();
    will_change_tri(t);
    tri_flags[t.value] = 0;
  } else {
    t = TriId{num_slots()};
    tri_flags.push_back(0);
    corner.resize(corner.size() + 3);
    twin.resize(twin.size() + 3);
    side_flags.resize(side_flags.size() + 3);
  }
  const std::uint32_t b3 = 3 * t.value;
  corner[b3] = a, corner[b3 + 1] = b, corner[b3 + 2] = c;
  twin[b3] = twin[b3 + 1] = twin[b3 + 2] = Side{};
  side_flags[b3] = side_flags[b3 + 1] = side_flags[b3 + 2] = 0;
  // Keep an out_side that is still good: the new triangle is not linked yet.
  for (const VertexId v : {a, b, c}) will_change_vertex(v);
  if (!out_side_ok(a)) out_side[a.value] = Side{b3};
  if (!out_side_ok(b)) out_side[b.value] = Side{b3 + 1};
  if (!out_side_ok(c)) out_side[c.value] = Side{b3 + 2};
  return t;
}

void TriangleStore::kill_triangle(TriId t) {
  SM_ASSERT(alive(t), "kill_triangle on a dead triangle");
  will_change_tri(t);
  // Repair out_side first, while all three twins are still readable.
  for (std::uint32_t e = 0; e < 3; ++e) {
    const Side s = side_of(t, e);
    const VertexId v = corner[s.value];
    if (out_side[v.value] != s) continue;
    will_change_vertex(v);
    const Side o = twin[s.value];                 // dest -> v: next(o) leaves v
    const Side p = twin[prev(s).value];           // v -> apex
    out_side[v.value] = o.valid() ? next(o) : p;
  }
  for (std::uint32_t e = 0; e < 3; ++e) {
    const Side s = side_of(t, e);
    const Side o = twin[s.value];
    will_change_tri_of(o);
    if (o.valid()) twin[o.value] = Side{};
    twin[s.value] = Side{};
  }
  tri_flags[t.value] = kDead;
  free_tris.push_back(t);
}

void TriangleStore::rebuild_out_side() {
  for (std::uint32_t v = 0; v < xy.size(); ++v) will_change_vertex(VertexId{v});
  out_side.assign(xy.size(), Side{});
  for (std::uint32_t s = 0; s < corner.size(); ++s)
    if (!(tri_flags[s / 3] & kDead)) out_side[corner[s].value] = Side{s};
}

void TriangleStore::set_edge_flags(Side s, std::uint8_t f) {
  will_change_tri_of(s);
  will_change_tri_of(twin[s.value]);
  side_flags[s.value] |= f;
  const Side o = twin[s.value];
  if (o.valid()) side_flags[o.value] |= f;
}

void TriangleStore::clear_edge_flags(Side s, std::uint8_t f) {
  will_change_tri_of(s);
  will_change_tri_of(twin[s.value]);
  side_flags[s.value] &= static_cast<std::uint8_t>(~f);
  const Side o = twin[s.value];
  if (o.valid()) side_flags[o.value] &= static_cast<std::uint8_t>(~f);
}

Side TriangleStore::side_between(VertexId a, VertexId b, bool* overrun) const {
  const Side start = out_side[a.value];
  if (!start.valid()) return Side{};
  // Each triangle of a's fan is met once each way: a longer walk is a corrupt fan.
  const std::uint32_t limit = num_slots() + 1;
  // Counter-clockwise around a: twin(prev(s)) leaves a in the next triangle.
  Side s = start;
  std::uint32_t steps = 0;
  do {
    if (dest(s) == b) return s;
    s = twin[prev(s).value];
  } while (s.valid() && s != start && ++steps < limit);
  if (s.valid()) {
    if (s != start && overrun) *overrun = true;
    return Side{};
  }
  // Hit the hull: go clockwise from the start, next(twin(s)) leaves a.
  s = start;
  for (steps = 0; steps < limit; ++steps) {
    const Side o = twin[s.value];
    if (!o.valid()) return Side{};
    s = next(o);
    if (dest(s) == b) return s;
  }
  if (overrun) *overrun = true;
  return Side{};
}

Side TriangleStore::flip(Side s) {
  //        c                  c
  //      /   \               / | \    new edge c-d
  //     a -s-> b     =>     a  |  b
  //      \   /               \ | /
  //        d                  d
  const Side ts = twin[s.value];
  SM_ASSERT(ts.valid(), "flip of a hull edge");
  const TriId t1 = tri_of(s), t2 = tri_of(ts);
  const VertexId a = org(s), b = dest(s), c = apex(s), d = apex(ts);
  const Side s_bc = next(s), s_ca = prev(s), s_ad = next(ts), s_db = prev(ts);
  const Side o_bc = twin[s_bc.value], o_ca = twin[s_ca.value];
  const Side o_ad = twin[s_ad.value], o_db = twin[s_db.value];
  const std::uint8_t f_bc = side_flags[s_bc.value], f_ca = side_flags[s_ca.value];
  const std::uint8_t f_ad = side_flags[s_ad.value], f_db = side_flags[s_db.value];
  // t1 = (c, a, d): sides c->a, a->d, d->c.  t2 = (d, b, c): sides d->b, b->c, c->d.
  const std::uint32_t b1 = 3 * t1.value, b2 = 3 * t2.value;
  will_change_tri(t1);
  will_change_tri(t2);
  for (const VertexId v : {a, b, c, d}) will_change_vertex(v);
  corner[b1] = c, corner[b1 + 1] = a, corner[b1 + 2] = d;
  corner[b2] = d, corner[b2 + 1] = b, corner[b2 + 2] = c;
  side_flags[b1] = f_ca, side_flags[b1 + 1] = f_ad, side_flags[b1 + 2] = 0;
  side_flags[b2] = f_db, side_flags[b2 + 1] = f_bc, side_flags[b2 + 2] = 0;
  link(Side{b1}, o_ca);
  link(Side{b1 + 1}, o_ad);
  link(Side{b2}, o_db);
  link(Side{b2 + 1}, o_bc);
  link(Side{b1 + 2}, Side{b2 + 2});
  out_side[c.value] = Side{b1};
  out_side[a.value] = Side{b1 + 1};
  out_side[d.value] = Side{b2};
  out_side[b.value] = Side{b2 + 1};
  return Side{b1 + 2};
}

void TriangleStore::compact() {
  SM_ASSERT(!undo_link.journal, "a store renumbered under an undo journal");
  std::vector<std::uint32_t> new_id(num_slots(), TriId::kNone);
  std::uint32_t n = 0;
  for (std::uint32_t t = 0; t < num_slots(); ++t)
    if (!(tri_flags[t] & kDead)) new_id[t] = n++;
  auto map_side = [&](Side s) { return s.valid() ? Side{3 * new_id[s.value / 3] + s.value % 3} : s; };
  for (std::uint32_t t = 0; t < num_slots(); ++t) {
    const std::uint32_t nt = new_id[t];
    if (nt == TriId::kNone) continue;
    for (std::uint32_t e = 0; e < 3; ++e) {
      corner[3 * nt + e] = corner[3 * t + e];
      twin[3 * nt + e] = map_side(twin[3 * t + e]);
      side_flags[3 * nt + e] = side_flags[3 * t + e];
    }
    tri_flags[nt] = tri_flags[t];
  }
  corner.resize(3 * n);
  twin.resize(3 * n);
  side_flags.resize(3 * n);
  tri_flags.resize(n);
  free_tris.clear();
  for (Side& s : out_side) s = map_side(s);
}

namespace {

// Moves v[old] to v[map[old]] for every mapped old index (an out-of-place
// pass, one array at a time, so the extra memory is one array).
template <class T>
void permute(std::vector<T>& v, const std::vector<std::uint32_t>& map, std::size_t n, std::uint32_t stride) {
  std::vector<T> out(n * stride);
  for (std::size_t i = 0; i < map.size(); ++i)
    if (map[i] != TriId::kNone)
      for (std::uint32_t e = 0; e < stride; ++e) out[std::size_t{map[i]} * stride + e] = v[i * stride + e];
  v.swap(out);
}

}  // namespace

void TriangleStore::sort_spatially(std::uint32_t first_movable, std::vector<std::uint32_t>& new_slot,
                                   std::vector<std::uint32_t>& new_vertex) {
  SM_ASSERT(!undo_link.journal, "a store renumbered under an undo journal");
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (const Vec2& p : xy) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  // Halves keep the span finite for coordinates near the double range.
  const double half_span = std::max(0.5 * hi.x - 0.5 * lo.x, 0.5 * hi.y - 0.5 * lo.y);
  const double scale = half_span > 0 ? 65535.0 / half_span : 0.0;
  // (rank, slot) sorted by rank in three 11-bit counting passes (2048
  // counters stay in L1). A triangle's place is its first corner's, ranked
  // in one streaming pass over the vertices: the gather per triangle then
  // reads 4 bytes instead of a 16-byte position.
  const auto cell = [&](double u, double u0) {
    return static_cast<std::uint32_t>(std::clamp((0.5 * u - 0.5 * u0) * scale, 0.0, 65535.0));
  };
  std::vector<std::uint32_t> rank(xy.size());
  for (std::size_t v = 0; v < xy.size(); ++v) rank[v] = hilbert_index(cell(xy[v].x, lo.x), cell(xy[v].y, lo.y), 16);
  std::vector<std::uint64_t> keys, tmp;
  keys.reserve(num_triangles());
  for (std::uint32_t t = 0; t < num_slots(); ++t)
    if (!(tri_flags[t] & kDead)) keys.push_back(std::uint64_t{rank[corner[3 * t].value]} << 32 | t);
  rank = {};
  tmp.resize(keys.size());
  for (int shift = 32; shift < 64; shift += 11) {
    std::uint32_t count[2049] = {};
    for (const std::uint64_t k : keys) ++count[((k >> shift) & 0x7FF) + 1];
    for (std::size_t i = 1; i < 2049; ++i) count[i] += count[i - 1];
    for (const std::uint64_t k : keys) tmp[count[(k >> shift) & 0x7FF]++] = k;
    keys.swap(tmp);
  }
  const std::uint32_t n = static_cast<std::uint32_t>(keys.size());
  new_slot.assign(num_slots(), TriId::kNone);
  for (std::uint32_t i = 0; i < n; ++i) new_slot[static_cast<std::uint32_t>(keys[i])] = i;
  new_vertex.assign(num_vertices(), VertexId::kNone);
  for (std::uint32_t v = 0; v < first_movable && v < num_vertices(); ++v) new_vertex[v] = v;
  std::uint32_t nv = std::min(first_movable, num_vertices());
  for (const std::uint64_t k : keys) {
    const std::uint32_t t = static_cast<std::uint32_t>(k);
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t v = corner[3 * t + e].value;
      if (new_vertex[v] == VertexId::kNone) new_vertex[v] = nv++;
    }
  }
  for (std::uint32_t v = 0; v < num_vertices(); ++v)
    if (new_vertex[v] == VertexId::kNone) new_vertex[v] = nv++;
  keys = {};
  tmp = {};
  for (Side& s : twin)
    if (s.valid()) s = Side{3 * new_slot[s.value / 3] + s.value % 3};
  for (VertexId& v : corner) v = VertexId{new_vertex[v.value]};
  permute(corner, new_slot, n, 3);
  permute(twin, new_slot, n, 3);
  permute(side_flags, new_slot, n, 3);
  permute(tri_flags, new_slot, n, 1);
  permute(xy, new_vertex, num_vertices(), 1);
  free_tris.clear();
  rebuild_out_side();
}

void TriangleStore::clear() {
  SM_ASSERT(!undo_link.journal, "a store renumbered under an undo journal");
  xy.clear();
  out_side.clear();
  corner.clear();
  twin.clear();
  side_flags.clear();
  tri_flags.clear();
  free_tris.clear();
}

void TriangleStore::reserve(std::uint32_t vertices, std::uint32_t triangles) {
  xy.reserve(vertices);
  out_side.reserve(vertices);
  corner.reserve(3 * std::size_t{triangles});
  twin.reserve(3 * std::size_t{triangles});
  side_flags.reserve(3 * std::size_t{triangles});
  tri_flags.reserve(triangles);
}

bool build_triangulation(std::vector<Vec2> xy, const std::vector<std::array<std::uint32_t, 3>>& tris,
                         TriangleStore& out) {
  out.clear();
  const auto nv = static_cast<std::uint32_t>(xy.size());
  out.xy = std::move(xy);
  out.out_side.assign(nv, Side{});
  for (const auto& t : tris) {
    if (t[0] >= nv || t[1] >= nv || t[2] >= nv) {
      out.clear();
      return false;
    }
    out.add_triangle(VertexId{t[0]}, VertexId{t[1]}, VertexId{t[2]});
  }
  // Sort directed edges (org, dest, side); the twin of a -> b is b -> a.
  struct E {
    std::uint32_t a, b, s;
  };
  std::vector<E> es;
  es.reserve(out.corner.size());
  for (std::uint32_t s = 0; s < out.corner.size(); ++s)
    es.push_back({out.corner[s].value, out.corner[next(Side{s}).value].value, s});
  std::sort(es.begin(), es.end(), [](const E& x, const E& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  for (std::size_t i = 0; i + 1 < es.size(); ++i)
    if (es[i].a == es[i + 1].a && es[i].b == es[i + 1].b) {
      out.clear();
      return false;
    }
  for (const E& e : es) {
    const auto it = std::lower_bound(es.begin(), es.end(), E{e.b, e.a, 0},
                                     [](const E& x, const E& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    if (it != es.end() && it->a == e.b && it->b == e.a) out.twin[e.s] = Side{it->s};
  }
  return true;
}

void TriangleStore::save_for_undo(TriId t) { undo_link.journal->save_tri(*this, t.value); }

void TriangleStore::save_for_undo(VertexId v) { undo_link.journal->save_vertex(*this, v.value); }

}  // namespace sm
