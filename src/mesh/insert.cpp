// Constrained Bowyer-Watson point insertion on the flat store.
#include "mesh/insert.h"

#include <cmath>

#include "mesh/cavity.h"
#include "mesh/geometry.h"
#include "mesh/locate.h"

namespace sm {

namespace {
// Visited triangles are found by scanning up to this many slots.
constexpr std::size_t kScanned = 16;
}

TriId PointInserter::locate(Vec2 c, TriId hint) {
  // The predicates are exact for finite inputs only: a constructed point at infinity
  // (the circumcentre of a triangle flat to double precision) is in no triangle.
  if (!std::isfinite(c.x) || !std::isfinite(c.y)) return TriId{};
  // A random first side at every step (mesh/locate.h): the triangulation is constrained,
  // not Delaunay, where a fixed rotation could cycle.
  struct Walker : StoreWalker {
    PointInserter* self;
    std::uint32_t first_side(std::uint32_t, std::uint64_t) const { return self->rng_.below3(); }
  } w{{m_, st_}, this};
  const WalkResult r = walk_to(w, c, hint.value, m_.num_slots());
  stats.walk_steps += r.steps;
  switch (r.end) {
    case WalkEnd::Found: return TriId{r.tri};
    case WalkEnd::Blocked: return TriId{};
    case WalkEnd::StepLimit: break;
  }
  return scan_for(w, c, hint);
}

InsertOutcome PointInserter::insert(Vec2 c, TriId t0, CavityCheck* check) {
  if (!std::isfinite(c.x) || !std::isfinite(c.y)) return InsertOutcome::Outside;
  const std::uint32_t nv = m_.num_vertices();
  for (std::uint32_t e = 0; e < 3; ++e)
    if (m_.pos(m_.vertex(t0, e)) == c) return InsertOutcome::Duplicate;
  for (std::uint32_t e = 0; e < 3; ++e) container_[e] = m_.vertex(t0, e);
  bound_.clear();
  // The cavity (mesh/cavity.h) in the store, stopped by constrained and hull sides.
  // Visited triangles are cavity_ + stack_. Small cavities (nearly all) find them by a
  // scan of those few slots, which saves a cache miss on tri_flags for every neighbour
  // tested; large ones switch to kMark.
  struct Host {
    PointInserter& in;
    Vec2 point;
    std::uint32_t nverts;
    bool marked = false, visible = true;
    void start(std::uint32_t) {}
    bool neighbour(std::uint32_t t, std::uint32_t e, std::uint32_t& nt) const {
      const Side s{3 * t + e};
      const Side o = in.m_.twin[s.value];
      if (!o.valid() || in.m_.constrained(s)) return false;
      nt = o.value / 3;
      return true;
    }
    bool visited(std::uint32_t nt) const {
      if (marked) return (in.m_.tri_flags[nt] & kMark) != 0;
      for (const std::uint32_t x : in.cavity_)
        if (x == nt) return true;
      for (const std::uint32_t x : in.stack_)
        if (x == nt) return true;
      return false;
    }
    bool in_conflict(std::uint32_t nt) const {
      const TriangleStore& m = in.m_;
      const VertexId a = m.vertex(TriId{nt}, 0), b = m.vertex(TriId{nt}, 1), d = m.vertex(TriId{nt}, 2);
      return incircle_sos(m.pos(a), m.pos(b), m.pos(d), point, a.value, b.value, d.value, nverts, in.st_) ==
             Sign::Positive;
    }
    void visit(std::uint32_t nt) {
      if (marked) {
        in.m_.will_change_tri(TriId{nt});
        in.m_.tri_flags[nt] |= kMark;
      } else if (in.cavity_.size() + in.stack_.size() > kScanned) {
        marked = true;
        for (const std::uint32_t x : in.cavity_) in.m_.will_change_tri(TriId{x}), in.m_.tri_flags[x] |= kMark;
        for (const std::uint32_t x : in.stack_) in.m_.will_change_tri(TriId{x}), in.m_.tri_flags[x] |= kMark;
      }
    }
    void boundary(std::uint32_t t, std::uint32_t e) {
      const Side s{3 * t + e};
      const VertexId a = in.m_.org(s), b = in.m_.dest(s);
      if (orient2d(in.m_.pos(a), in.m_.pos(b), point, in.st_) != Sign::Positive) visible = false;
      in.bound_.push_back({a, b, in.m_.twin[s.value], in.m_.side_flags[s.value]});
    }
  } host{*this, c, nv};
  cavity_search(host, t0.value, stack_, cavity_);
  if (host.marked)
    for (std::uint32_t t : cavity_) m_.tri_flags[t] &= static_cast<std::uint8_t>(~kMark);
  if (!host.visible) return InsertOutcome::NotVisible;
  // The boundary must close: each edge's end is the start of another. It always does in a
  // consistent triangulation; twins that do not match (a corrupt store) would otherwise
  // leave a new side unpaired. Checked before any change.
  const std::size_t k = bound_.size();
  next_.resize(k);
  if (!fan_pairs(
          bound_, [](VertexId v) { return v.value; }, std::size_t{m_.num_vertices()} + 1, vmap_,
          [this](std::size_t i, std::size_t j) { next_[i] = static_cast<std::uint32_t>(j); }))
    return InsertOutcome::NotVisible;
  if (check) {
    edges_.clear();
    for (const Bound& bd : bound_) edges_.push_back({bd.a, bd.b});
    if (!check->accept(c, cavity_.size(), edges_)) return InsertOutcome::Rejected;
  }
  stats.cavity_triangles += cavity_.size();
  const VertexId v = m_.add_vertex(c);
  // Slots: the cavity's, then dead ones, then new ones (k = cavity + 2).
  while (cavity_.size() < k) {
    std::uint32_t t;
    if (!m_.free_tris.empty()) {
      t = m_.free_tris.back().value;
      m_.free_tris.pop_back();
    } else {
      t = m_.num_slots();
      m_.tri_flags.push_back(0);
      m_.corner.resize(m_.corner.size() + 3);
      m_.twin.resize(m_.twin.size() + 3);
      m_.side_flags.resize(m_.side_flags.size() + 3);
    }
    cavity_.push_back(t);
  }
  for (std::size_t i = 0; i < k; ++i) {
    const Bound& bd = bound_[i];
    const std::uint32_t t = cavity_[i], s = 3 * t;
    m_.will_change_tri(TriId{t});
    m_.tri_flags[t] = 0;
    m_.corner[s] = bd.a, m_.corner[s + 1] = bd.b, m_.corner[s + 2] = v;
    m_.side_flags[s] = bd.flags, m_.side_flags[s + 1] = 0, m_.side_flags[s + 2] = 0;
    m_.link(Side{s}, bd.outer);
    if (keep_out_side) m_.will_change_vertex(bd.a), m_.out_side[bd.a.value] = Side{s};
  }
  if (keep_out_side) m_.out_side[v.value] = Side{3 * cavity_[0] + 2};
  // Link b -> v of the triangle on (a, b) with v -> b of the one on (b, c).
  for (std::size_t i = 0; i < k; ++i) m_.link(Side{3 * cavity_[i] + 1}, Side{3 * cavity_[next_[i]] + 2});
  last_ = v;
  created_ = k;
  return InsertOutcome::Inserted;
}

}  // namespace sm
