// Constrained Bowyer-Watson point insertion on the flat store.
#include "mesh/insert.h"

#include <cmath>

#include "mesh/geometry.h"
#include "mesh/locate.h"

namespace sm {

namespace {
// Visited triangles are found by scanning up to this many slots.
constexpr std::size_t kScanned = 16;
}

std::uint32_t PointInserter::rand3() {
  rng_ ^= rng_ >> 12, rng_ ^= rng_ << 25, rng_ ^= rng_ >> 27;
  return static_cast<std::uint32_t>((((rng_ * 0x2545F4914F6CDD1Dull) >> 32) * 3) >> 32);
}

TriId PointInserter::locate(Vec2 c, TriId hint) {
  // The predicates are exact for finite inputs only: a constructed point at infinity
  // (the circumcentre of a triangle flat to double precision) is in no triangle.
  if (!std::isfinite(c.x) || !std::isfinite(c.y)) return TriId{};
  // A random first side at every step (mesh/locate.h): the triangulation is constrained,
  // not Delaunay, where a fixed rotation could cycle.
  struct Walker : StoreWalker {
    PointInserter* self;
    std::uint32_t first_side(std::uint32_t, std::uint64_t) const { return self->rand3(); }
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

InsertOutcome PointInserter::insert(Vec2 c, TriId t0) {
  if (!std::isfinite(c.x) || !std::isfinite(c.y)) return InsertOutcome::Outside;
  const std::uint32_t nv = m_.num_vertices();
  for (std::uint32_t e = 0; e < 3; ++e)
    if (m_.pos(m_.vertex(t0, e)) == c) return InsertOutcome::Duplicate;
  for (std::uint32_t e = 0; e < 3; ++e) container_[e] = m_.vertex(t0, e);
  cavity_.clear();
  bound_.clear();
  stack_.assign(1, t0.value);
  // Visited triangles are cavity_ + stack_. Small cavities (nearly all)
  // find them by a scan of those few slots, which saves a cache miss on
  // tri_flags for every neighbour tested; large ones switch to kMark.
  bool marked = false;
  const auto visited = [&](std::uint32_t nt) {
    if (marked) return (m_.tri_flags[nt] & kMark) != 0;
    for (const std::uint32_t x : cavity_)
      if (x == nt) return true;
    for (const std::uint32_t x : stack_)
      if (x == nt) return true;
    return false;
  };
  bool visible = true;
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    cavity_.push_back(t);
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      const Side o = m_.twin[s.value];
      if (o.valid() && !m_.constrained(s)) {
        const std::uint32_t nt = o.value / 3;
        if (visited(nt)) continue;
        const VertexId a = m_.vertex(TriId{nt}, 0), b = m_.vertex(TriId{nt}, 1), d = m_.vertex(TriId{nt}, 2);
        if (incircle_sos(m_.pos(a), m_.pos(b), m_.pos(d), c, a.value, b.value, d.value, nv, st_) == Sign::Positive) {
          stack_.push_back(nt);
          if (marked) {
            m_.tri_flags[nt] |= kMark;
          } else if (cavity_.size() + stack_.size() > kScanned) {
            marked = true;
            for (const std::uint32_t x : cavity_) m_.tri_flags[x] |= kMark;
            for (const std::uint32_t x : stack_) m_.tri_flags[x] |= kMark;
          }
          continue;
        }
      }
      const VertexId a = m_.org(s), b = m_.dest(s);
      if (orient2d(m_.pos(a), m_.pos(b), c, st_) != Sign::Positive) visible = false;
      bound_.push_back({a, b, o, m_.side_flags[s.value]});
    }
  }
  if (marked)
    for (std::uint32_t t : cavity_) m_.tri_flags[t] &= static_cast<std::uint8_t>(~kMark);
  if (!visible) return InsertOutcome::NotVisible;
  // The boundary must close: each edge's end is the start of another (j_of). It always
  // does in a consistent triangulation; twins that do not match (a corrupt store) would
  // otherwise send the search below past the end of bound_. Checked before any change.
  const std::size_t k = bound_.size();
  if (k > 32 && vmap_.size() < m_.num_vertices() + 1)
    vmap_.resize(m_.num_vertices() + m_.num_vertices() / 2 + 1, kNoIndex);
  if (k > 32)
    for (std::size_t i = 0; i < k; ++i) vmap_[bound_[i].a.value] = static_cast<std::uint32_t>(i);
  const auto j_of = [&](std::size_t i) -> std::size_t {
    if (k > 32) {
      const std::uint32_t j = vmap_[bound_[i].b.value];
      return j < k && bound_[j].a == bound_[i].b ? j : k;
    }
    std::size_t j = 0;
    while (j < k && bound_[j].a != bound_[i].b) ++j;
    return j;
  };
  for (std::size_t i = 0; i < k; ++i)
    if (j_of(i) == k) return InsertOutcome::NotVisible;
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
    m_.tri_flags[t] = 0;
    m_.corner[s] = bd.a, m_.corner[s + 1] = bd.b, m_.corner[s + 2] = v;
    m_.side_flags[s] = bd.flags, m_.side_flags[s + 1] = 0, m_.side_flags[s + 2] = 0;
    m_.link(Side{s}, bd.outer);
    if (keep_out_side) m_.out_side[bd.a.value] = Side{s};
  }
  if (keep_out_side) m_.out_side[v.value] = Side{3 * cavity_[0] + 2};
  // Link b -> v of the triangle on (a, b) with v -> b of the one on (b, c).
  for (std::size_t i = 0; i < k; ++i) m_.link(Side{3 * cavity_[i] + 1}, Side{3 * cavity_[j_of(i)] + 2});
  last_ = v;
  created_ = k;
  return InsertOutcome::Inserted;
}

}  // namespace sm
