// Invariant checkers: topology (twins, orientation, fans), Delaunay, constraints.
#include "mesh/check.h"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

namespace sm {

CheckResult check_topology(const TriangleStore& m) {
  const std::uint32_t nv = m.num_vertices();
  const PlanarGeometry g{&m.xy};
  if (m.out_side.size() != nv) return {"out_side size differs from vertex count"};
  if (m.corner.size() != 3 * std::size_t{m.num_slots()} || m.twin.size() != m.corner.size() ||
      m.side_flags.size() != m.corner.size())
    return {"per-side arrays do not match the triangle slot count"};
  std::uint32_t dead = 0;
  std::vector<std::uint32_t> incident(nv, 0);
  std::vector<std::uint64_t> edges;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (m.tri_flags[t] & kDead) {
      ++dead;
      continue;
    }
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      const VertexId v = m.org(s);
      if (!v.valid() || v.value >= nv) return {fmt::format("triangle {} has invalid corner {}", t, v.value)};
      ++incident[v.value];
      edges.push_back(std::uint64_t{v.value} << 32 | m.dest(s).value);
      const Side o = m.twin[s.value];
      if (!o.valid()) continue;
      if (o.value >= m.corner.size() || !m.alive(tri_of(o)))
        return {fmt::format("side {} of triangle {} has a dead or invalid twin {}", e, t, o.value)};
      if (m.twin[o.value] != s)
        return {fmt::format("twin of side {} is {} but its twin is {}", s.value, o.value, m.twin[o.value].value)};
      if (m.org(o) != m.dest(s) || m.dest(o) != m.org(s))
        return {fmt::format("side {} ({}->{}) and twin {} ({}->{}) do not match", s.value, m.org(s).value,
                            m.dest(s).value, o.value, m.org(o).value, m.dest(o).value)};
      if (m.side_flags[s.value] != m.side_flags[o.value])
        return {fmt::format("flags differ across edge {}-{}", m.org(s).value, m.dest(s).value)};
    }
    const VertexId a = m.vertex(TriId{t}, 0), b = m.vertex(TriId{t}, 1), c = m.vertex(TriId{t}, 2);
    if (a == b || b == c || a == c)
      return {fmt::format("triangle {} repeats a corner ({}, {}, {})", t, a.value, b.value, c.value)};
    if (g.orient(a, b, c) != Sign::Positive)
      return {fmt::format("triangle {} ({}, {}, {}) is not counter-clockwise", t, a.value, b.value, c.value)};
  }
  if (dead != m.free_tris.size())
    return {fmt::format("{} dead triangles but {} on the free list", dead, m.free_tris.size())};
  for (TriId t : m.free_tris)
    if (m.alive(t)) return {fmt::format("free list holds live triangle {}", t.value)};
  std::sort(edges.begin(), edges.end());
  if (auto it = std::adjacent_find(edges.begin(), edges.end()); it != edges.end())
    return {fmt::format("edge {}->{} appears twice", *it >> 32, *it & 0xFFFFFFFFu)};
  for (std::uint32_t v = 0; v < nv; ++v) {
    const Side s0 = m.out_side[v];
    if (incident[v] == 0) {
      if (s0.valid()) return {fmt::format("isolated vertex {} has out_side {}", v, s0.value)};
      continue;
    }
    if (!s0.valid() || s0.value >= m.corner.size() || !m.alive(tri_of(s0)) || m.org(s0).value != v)
      return {fmt::format("vertex {} has an invalid out_side", v)};
    // Walk the fan both ways; it must reach every incident triangle.
    std::uint32_t count = 1;
    Side s = m.twin[prev(s0).value];
    while (s.valid() && s != s0 && count <= incident[v]) ++count, s = m.twin[prev(s).value];
    if (!s.valid()) {
      s = s0;
      for (;;) {
        const Side o = m.twin[s.value];
        if (!o.valid()) break;
        s = next(o);
        if (++count > incident[v]) break;
      }
    }
    if (count != incident[v])
      return {fmt::format("vertex {} is not manifold: fan of {} triangles, {} incident", v, count, incident[v])};
  }
  return {};
}

CheckResult check_delaunay(const TriangleStore& m, const PlanarGeometry& g, bool canonical) {
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (m.tri_flags[t] & kDead) continue;
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      const Side o = m.twin[s.value];
      if (!o.valid() || m.constrained(s)) continue;
      const VertexId a = m.org(s), b = m.dest(s), c = m.apex(s), d = m.apex(o);
      const Sign in = canonical ? g.in_circle_sos(a, b, c, d) : g.in_circle(a, b, c, d);
      if (in == Sign::Positive)
        return {fmt::format("edge {}-{} is not Delaunay: vertex {} inside the circle of ({}, {}, {})", a.value,
                            b.value, d.value, a.value, b.value, c.value)};
    }
  }
  return {};
}

CheckResult check_constraints(const TriangleStore& m, const std::vector<std::pair<VertexId, VertexId>>& edges) {
  for (auto [a, b] : edges) {
    Side s = m.side_between(a, b);
    if (!s.valid()) s = m.side_between(b, a);
    if (!s.valid()) return {fmt::format("constrained edge {}-{} is missing", a.value, b.value)};
    if (!m.constrained(s)) return {fmt::format("edge {}-{} is present but not flagged constrained", a.value, b.value)};
  }
  return {};
}

}  // namespace sm
