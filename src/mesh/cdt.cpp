// Constrained edge recovery by swaps and removal of outside triangles.
//
// Recovering a -> b: find the triangle at a that the segment leaves through,
// walk the triangles it crosses (exact orient2d) collecting the crossed
// edges, then swap them (Sloan's queue: a non-convex quad waits for later,
// a new diagonal still crossing ab goes back in the queue). A crossed edge
// that is itself constrained means two constraints intersect: the paper's
// detection rule (section 3.2); it is reported and nothing is swapped. A
// vertex exactly on the segment splits it into two sub-edges.
#include "mesh/cdt.h"

#include <unordered_map>

#include <fmt/format.h>

namespace sm {
namespace {

std::uint64_t edge_key(VertexId a, VertexId b) {
  return a.value < b.value ? std::uint64_t{a.value} << 32 | b.value : std::uint64_t{b.value} << 32 | a.value;
}

// The side a -> b if present, else b -> a (hull edges have only one).
Side find_side(const TriangleStore& m, VertexId a, VertexId b) {
  const Side s = m.side_between(a, b);
  return s.valid() ? s : m.side_between(b, a);
}

// u, on the line through a and b, lies on the same side of a as b. Exact:
// only comparisons of coordinates.
bool same_direction(Vec2 a, Vec2 u, Vec2 b) {
  auto sgn = [](double p, double q) { return (p > q) - (p < q); };
  return sgn(u.x, a.x) == sgn(b.x, a.x) && sgn(u.y, a.y) == sgn(b.y, a.y);
}

class Recoverer {
 public:
  Recoverer(TriangleStore& m, const PlanarGeometry& g, RecoverResult& res) : m_(m), g_(g), res_(res) {}

  void recover(std::uint32_t i, VertexId a, VertexId b);
  std::unordered_map<std::uint64_t, std::uint32_t> owner;  // lookups only, never iterated

 private:
  bool flip_crossed(VertexId a, VertexId b);
  void restore_delaunay();
  void constrain(std::uint32_t i, Side s) {
    m_.set_edge_flags(s, kConstrained);
    owner.emplace(edge_key(m_.org(s), m_.dest(s)), i);
  }

  TriangleStore& m_;
  const PlanarGeometry& g_;
  RecoverResult& res_;
  std::vector<Edge> work_, queue_, fresh_;
};

void Recoverer::recover(std::uint32_t i, VertexId a0, VertexId b0) {
  work_.assign(1, {a0, b0});
  while (!work_.empty()) {
    // Plain variables, not a structured binding: the lambda below captures
    // them, which C++20 allows but clang 14 (the fuzz build) rejects.
    const Edge top = work_.back();
    const VertexId a = top.first, b = top.second;
    work_.pop_back();
    if (const Side s = find_side(m_, a, b); s.valid()) {
      if (a == a0 && b == b0) ++res_.stats.already_present;
      constrain(i, s);
      continue;
    }
    const Vec2 pa = g_.pos(a), pb = g_.pos(b);
    // The triangle (a, u, w) at a with u strictly right of ab and w strictly
    // left: the segment leaves it through edge u -> w.
    Side exit;
    VertexId split;
    const Side start = m_.out_side[a.value];
    auto try_side = [&](Side s) {
      const VertexId u = m_.dest(s), w = m_.apex(s);
      const Sign ou = g_.orient(a, b, u), ow = g_.orient(a, b, w);
      if (ou == Sign::Zero && same_direction(pa, g_.pos(u), pb)) split = u;
      else if (ow == Sign::Zero && same_direction(pa, g_.pos(w), pb)) split = w;
      else if (ou == Sign::Negative && ow == Sign::Positive) exit = next(s);
      return split.valid() || exit.valid();
    };
    // Round a's fan, each triangle met once each way (a longer turn is a corrupt fan, and
    // ends in the error below): counter-clockwise, then clockwise from the hull.
    bool done = false;
    Side s = start;
    std::uint32_t turn = 0;
    do {
      done = try_side(s);
      s = m_.twin[prev(s).value];
    } while (!done && s.valid() && s != start && ++turn <= m_.num_slots());
    if (!done && !s.valid()) {
      s = start;
      for (turn = 0; !done && turn <= m_.num_slots(); ++turn) {
        const Side o = m_.twin[s.value];
        if (!o.valid()) break;
        s = next(o);
        done = try_side(s);
      }
    }
    if (!done) {
      res_.error = fmt::format("cannot recover edge {}-{}: the segment leaves the triangulation", a.value, b.value);
      return;
    }
    // Walk along ab collecting crossed edges, until b or a vertex on ab.
    bool blocked = false;
    queue_.clear();
    // A straight segment enters each triangle once: a longer walk is a corrupt triangulation.
    for (std::uint32_t steps = 0; exit.valid(); ++steps) {
      if (steps > m_.num_slots()) {
        res_.error = fmt::format("cannot recover edge {}-{}: the walk along it did not end", a.value, b.value);
        return;
      }
      const VertexId u = m_.org(exit), w = m_.dest(exit);
      if (m_.constrained(exit)) {
        const auto it = owner.find(edge_key(u, w));
        res_.crossings.push_back({i, it == owner.end() ? kNoEdge : it->second, u, w});
        blocked = true;
      }
      queue_.push_back({u, w});
      const Side o = m_.twin[exit.value];
      if (!o.valid()) {
        res_.error = fmt::format("cannot recover edge {}-{}: the segment leaves the triangulation", a.value, b.value);
        return;
      }
      const VertexId x = m_.apex(o);
      if (x == b) break;
      const Sign ox = g_.orient(a, b, x);
      if (ox == Sign::Zero) {
        split = x;
        break;
      }
      exit = ox == Sign::Positive ? next(o) : prev(o);
    }
    if (split.valid()) {
      res_.touching.push_back({i, split});
      if (!blocked) {
        work_.push_back({split, b});
        work_.push_back({a, split});
      }
      continue;
    }
    if (blocked) continue;
    if (!flip_crossed(a, b)) return;
    const Side s_ab = find_side(m_, a, b);
    if (!s_ab.valid()) {
      res_.error = fmt::format("edge {}-{} missing after swaps", a.value, b.value);
      return;
    }
    constrain(i, s_ab);
    restore_delaunay();
  }
}

// Swaps the edges in queue_ until none crosses ab (Sloan 1993).
bool Recoverer::flip_crossed(VertexId a, VertexId b) {
  fresh_.clear();
  std::size_t head = 0;
  const std::size_t limit = 64 * queue_.size() * queue_.size() + 1024;
  std::size_t steps = 0;
  while (head < queue_.size()) {
    if (++steps > limit) {
      res_.error = fmt::format("edge {}-{}: swaps did not converge", a.value, b.value);
      return false;
    }
    const Edge e = queue_[head++];
    const Side s = find_side(m_, e.first, e.second);
    const VertexId u = m_.org(s), w = m_.dest(s), c = m_.apex(s), d = m_.apex(m_.twin[s.value]);
    if (g_.orient(c, u, d) != Sign::Positive || g_.orient(d, w, c) != Sign::Positive) {
      queue_.push_back(e);  // not convex yet: retry after other swaps
      continue;
    }
    m_.flip(s);
    ++res_.stats.flips;
    const Sign oc = g_.orient(a, b, c), od = g_.orient(a, b, d);
    if ((oc == Sign::Positive && od == Sign::Negative) || (oc == Sign::Negative && od == Sign::Positive))
      queue_.push_back({c, d});
    else
      fresh_.push_back({c, d});
  }
  return true;
}

// Lawson swaps over the edges created by the recovery until each is locally
// (constrained) Delaunay, ties broken by id as in delaunay().
void Recoverer::restore_delaunay() {
  bool changed = true;
  std::size_t rounds = 0;
  while (changed && rounds++ < 4 * fresh_.size() + 8) {
    changed = false;
    for (Edge& e : fresh_) {
      const Side s = find_side(m_, e.first, e.second);
      if (!s.valid() || m_.constrained(s)) continue;
      const Side t = m_.twin[s.value];
      if (!t.valid()) continue;
      const VertexId u = m_.org(s), w = m_.dest(s), c = m_.apex(s), d = m_.apex(t);
      if (g_.in_circle_sos(u, w, c, d) != Sign::Positive) continue;
      if (g_.orient(c, u, d) != Sign::Positive || g_.orient(d, w, c) != Sign::Positive) continue;
      m_.flip(s);
      ++res_.stats.delaunay_flips;
      e = {c, d};
      changed = true;
    }
  }
}

}  // namespace

RecoverResult recover_edges(TriangleStore& m, const PlanarGeometry& g, const std::vector<Edge>& edges) {
  RecoverResult res;
  Recoverer r(m, g, res);
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    if (!a.valid() || !b.valid() || a.value >= m.num_vertices() || b.value >= m.num_vertices()) {
      res.error = fmt::format("edge {}: vertex id out of range", i);
      return res;
    }
    if (a == b || g.pos(a) == g.pos(b)) {
      res.error = fmt::format("edge {} ({}-{}) has zero length", i, a.value, b.value);
      return res;
    }
    if (!m.out_side[a.value].valid() || !m.out_side[b.value].valid()) {
      res.error = fmt::format("edge {} ({}-{}) uses a vertex that is not in the triangulation", i, a.value, b.value);
      return res;
    }
    r.recover(i, a, b);
    if (!res.ok()) return res;
  }
  return res;
}

DomainResult remove_outside(TriangleStore& m, const PlanarGeometry& g, const std::vector<Loop>& loops) {
  DomainResult res;
  enum : std::uint8_t { kUnknown = 0, kIn = 1, kOut = 2 };
  std::vector<std::uint8_t> label(m.num_slots(), kUnknown), wall(m.corner.size(), 0);
  std::vector<std::pair<std::uint32_t, std::uint8_t>> seeds;
  std::vector<Side> loop_sides;
  for (std::size_t li = 0; li < loops.size(); ++li) {
    const auto& v = loops[li].v;
    const std::size_t n = v.size();
    if (n < 3) return {fmt::format("loop {} has fewer than three vertices", li)};
    // Orientation, exactly: the lexicographically smallest vertex is convex.
    std::size_t k = 0;
    for (std::size_t j = 1; j < n; ++j) {
      const Vec2 p = g.pos(v[j]), q = g.pos(v[k]);
      if (p.x < q.x || (p.x == q.x && p.y < q.y)) k = j;
    }
    const Sign o = g.orient(v[(k + n - 1) % n], v[k], v[(k + 1) % n]);
    if (o == Sign::Zero) return {fmt::format("loop {} is degenerate at vertex {}", li, v[k].value)};
    // The interior of the loop is left of its counter-clockwise edges. Only
    // the interior side is seeded (inside for an outer loop, outside for a
    // hole): the exterior side belongs to whatever encloses the loop, found
    // by the flood fill. So a loop lying outside every outer loop (an island
    // beyond the outer boundary) is harmless.
    const bool ccw = o == Sign::Positive;
    for (std::size_t j = 0; j < n; ++j) {
      VertexId p = v[j], q = v[(j + 1) % n];
      if (!ccw) std::swap(p, q);
      const Side in = m.side_between(p, q), out = m.side_between(q, p);
      if (!in.valid() && !out.valid())
        return {fmt::format("loop {}: edge {}-{} is not in the triangulation", li, p.value, q.value)};
      for (Side s : {in, out})
        if (s.valid()) wall[s.value] = 1, loop_sides.push_back(s);
      if (in.valid()) seeds.push_back({tri_of(in).value, loops[li].hole ? kOut : kIn});
    }
  }
  // Triangles on the hull, behind a side that is no loop edge, are outside.
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.alive(tri_of(Side{s})) && !m.twin[s].valid() && !wall[s]) seeds.push_back({s / 3, kOut});
  std::vector<std::uint32_t> stack;
  for (auto [t0, lab] : seeds) {
    if (label[t0] == lab) continue;
    if (label[t0] != kUnknown)
      return {fmt::format("inconsistent loops: triangle {} near ({}, {}) is both inside and outside", t0,
                          g.pos(m.vertex(TriId{t0}, 0)).x, g.pos(m.vertex(TriId{t0}, 0)).y)};
    label[t0] = lab;
    stack.assign(1, t0);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (std::uint32_t e = 0; e < 3; ++e) {
        const std::uint32_t s = 3 * t + e;
        const Side o = m.twin[s];
        if (wall[s] || !o.valid()) continue;
        const std::uint32_t nt = o.value / 3;
        if (label[nt] == lab) continue;
        if (label[nt] != kUnknown)
          return {fmt::format("inconsistent loops: triangle {} near ({}, {}) is both inside and outside", nt,
                              g.pos(m.vertex(TriId{nt}, 0)).x, g.pos(m.vertex(TriId{nt}, 0)).y)};
        label[nt] = lab;
        stack.push_back(nt);
      }
    }
  }
  for (Side s : loop_sides) m.set_edge_flags(s, kConstrained | kBoundary);
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t}) && label[t] != kIn) {
      m.kill_triangle(TriId{t});
      ++res.removed;
    }
  m.rebuild_out_side();
  return res;
}

}  // namespace sm
