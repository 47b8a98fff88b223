// del2d: circumcentre insertion driven by a binary heap of {priority, TriId,
// stamp}; stale entries (slot rewritten since) are skipped. The cavity is
// the Bowyer-Watson conflict region grown across non-constrained edges only,
// which keeps the triangulation constrained Delaunay.
#include "mesh/refine.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <span>
#include <vector>

#include "mesh/geometry.h"
#include "mesh/quality.h"

namespace sm {
namespace {

constexpr std::uint32_t kNo = 0xFFFFFFFFu;

// A heap entry {priority, TriId, stamp} packed in 64 bits: the priority as
// float bits (positive floats order like their bit patterns) above the
// complemented id (ties: smaller id first). The stamp is implicit: queued_[t]
// holds the priority bits the slot's current triangle was queued with, so an
// entry is stale when the slot died, was rewritten or was already served.
// Half the bytes of a {double, id, stamp} record: the heap is the hot data.
using Entry = std::uint64_t;

class Refiner {
 public:
  Refiner(TriangleStore& m, const RefineOptions& opt, RefineResult& res)
      : m_(m), opt_(opt), res_(res), st_(&res.stats.predicates), rng_(opt.seed | 1) {}
  void run();

 private:
  void consider(std::span<const std::uint32_t> tris);
  std::uint32_t locate(Vec2 c, std::uint32_t t);
  bool insert(Vec2 c, std::uint32_t t0);
  std::uint32_t rand3() {
    rng_ ^= rng_ >> 12, rng_ ^= rng_ << 25, rng_ ^= rng_ >> 27;
    return static_cast<std::uint32_t>((((rng_ * 0x2545F4914F6CDD1Dull) >> 32) * 3) >> 32);
  }

  TriangleStore& m_;
  const RefineOptions& opt_;
  RefineResult& res_;
  PredicateStats* st_;
  std::uint64_t rng_;
  std::vector<std::uint32_t> queued_;  // per slot: priority bits when queued, 0 when not
  std::vector<Entry> heap_;
  struct Bound {
    VertexId a, b;
    Side outer;
    std::uint8_t flags;
  };
  std::vector<std::uint32_t> stack_, cavity_, vmap_;
  std::vector<Bound> bound_;
  std::vector<Vec2> cc_;
  std::vector<double> h_;
};

// Queues the triangles whose circumradius exceeds the bound, with the size
// field evaluated once for the whole batch of circumcentres.
void Refiner::consider(std::span<const std::uint32_t> tris) {
  cc_.resize(tris.size());
  h_.resize(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const TriId t{tris[i]};
    cc_[i] = circumcentre(m_.pos(m_.vertex(t, 0)), m_.pos(m_.vertex(t, 1)), m_.pos(m_.vertex(t, 2)));
  }
  if (opt_.size_at) opt_.size_at(cc_, h_);
  else std::fill(h_.begin(), h_.end(), opt_.size);
  const double limit2 = opt_.radius_limit * opt_.radius_limit;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const std::uint32_t t = tris[i];
    const double h = h_[i];
    if (!(h > 0) || !std::isfinite(h)) {
      if (res_.error.empty()) res_.error = "mesh size must be positive and finite (got " + std::to_string(h) + ")";
      return;
    }
    const double q = norm2(cc_[i] - m_.pos(m_.vertex(TriId{t}, 0))) / (h * h);
    queued_[t] = 0;
    if (q > limit2) {
      const std::uint32_t bits = std::bit_cast<std::uint32_t>(static_cast<float>(q));
      queued_[t] = bits;
      heap_.push_back(std::uint64_t{bits} << 32 | (~t & 0xFFFFFFFFu));
      std::push_heap(heap_.begin(), heap_.end());
    }
  }
}

// Visibility walk towards c that never crosses a constrained or hull edge:
// kNo when c lies beyond one (outside the domain, or across a constraint).
std::uint32_t Refiner::locate(Vec2 c, std::uint32_t t) {
  for (std::uint32_t steps = 0; steps < 1000000; ++steps) {
    const std::uint32_t e0 = rand3();
    std::uint32_t k = 0, e = e0;
    for (; k < 3; ++k, e = e == 2 ? 0 : e + 1) {
      const Side s{3 * t + e};
      if (orient2d(m_.pos(m_.org(s)), m_.pos(m_.dest(s)), c, st_) == Sign::Negative) break;
    }
    if (k == 3) return t;
    const Side s{3 * t + e};
    const Side o = m_.twin[s.value];
    if (!o.valid() || m_.constrained(s)) return kNo;
    t = o.value / 3;
    ++res_.stats.walk_steps;
  }
  return kNo;
}

bool Refiner::insert(Vec2 c, std::uint32_t t0) {
  const std::uint32_t nv = m_.num_vertices();
  for (std::uint32_t e = 0; e < 3; ++e)
    if (m_.pos(m_.vertex(TriId{t0}, e)) == c) return false;
  cavity_.clear();
  bound_.clear();
  stack_.assign(1, t0);
  m_.tri_flags[t0] |= kMark;
  bool ok = true;
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    cavity_.push_back(t);
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      const Side o = m_.twin[s.value];
      if (o.valid() && !m_.constrained(s)) {
        const std::uint32_t nt = o.value / 3;
        if (m_.tri_flags[nt] & kMark) continue;
        const VertexId a = m_.vertex(TriId{nt}, 0), b = m_.vertex(TriId{nt}, 1), d = m_.vertex(TriId{nt}, 2);
        if (incircle_sos(m_.pos(a), m_.pos(b), m_.pos(d), c, a.value, b.value, d.value, nv, st_) == Sign::Positive) {
          m_.tri_flags[nt] |= kMark;
          stack_.push_back(nt);
          continue;
        }
      }
      const VertexId a = m_.org(s), b = m_.dest(s);
      if (orient2d(m_.pos(a), m_.pos(b), c, st_) != Sign::Positive) ok = false;  // c would not see this edge
      bound_.push_back({a, b, o, m_.side_flags[s.value]});
    }
  }
  for (std::uint32_t t : cavity_) m_.tri_flags[t] &= static_cast<std::uint8_t>(~kMark);
  if (!ok) return false;
  res_.stats.cavity_triangles += cavity_.size();
  const VertexId v = m_.add_vertex(c);
  const std::size_t k = bound_.size();
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
      queued_.push_back(0);
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
    m_.out_side[bd.a.value] = Side{s};
  }
  m_.out_side[v.value] = Side{3 * cavity_[0] + 2};
  if (k <= 32) {
    for (std::size_t i = 0; i < k; ++i) {
      std::size_t j = 0;
      while (bound_[j].a != bound_[i].b) ++j;
      m_.link(Side{3 * cavity_[i] + 1}, Side{3 * cavity_[j] + 2});
    }
  } else {
    if (vmap_.size() < m_.num_vertices()) vmap_.resize(m_.num_vertices() + m_.num_vertices() / 2, kNo);
    for (std::size_t i = 0; i < k; ++i) vmap_[bound_[i].a.value] = cavity_[i];
    for (std::size_t i = 0; i < k; ++i) m_.link(Side{3 * cavity_[i] + 1}, Side{3 * vmap_[bound_[i].b.value] + 2});
  }
  consider(std::span<const std::uint32_t>(cavity_.data(), k));
  return true;
}

void Refiner::run() {
  queued_.assign(m_.num_slots(), 0);
  std::vector<std::uint32_t> live;
  for (std::uint32_t t = 0; t < m_.num_slots(); ++t)
    if (m_.alive(TriId{t})) live.push_back(t);
  for (std::size_t i = 0; i < live.size(); i += 4096)
    consider(std::span<const std::uint32_t>(live.data() + i, std::min<std::size_t>(4096, live.size() - i)));
  while (!heap_.empty() && res_.error.empty()) {
    std::pop_heap(heap_.begin(), heap_.end());
    const Entry top = heap_.back();
    heap_.pop_back();
    ++res_.stats.pops;
    const std::uint32_t t = ~static_cast<std::uint32_t>(top);
    if (!m_.alive(TriId{t}) || queued_[t] != static_cast<std::uint32_t>(top >> 32)) {
      ++res_.stats.stale;
      continue;
    }
    queued_[t] = 0;
    if (m_.num_vertices() >= opt_.max_vertices) {
      res_.error = "refinement stopped at the vertex limit";
      return;
    }
    const Vec2 a = m_.pos(m_.vertex(TriId{t}, 0)), b = m_.pos(m_.vertex(TriId{t}, 1));
    const Vec2 cc = circumcentre(a, b, m_.pos(m_.vertex(TriId{t}, 2)));
    const std::uint32_t loc = locate(cc, t);
    if (loc == kNo || !insert(cc, loc)) {
      ++res_.stats.rejected;
      continue;
    }
    ++res_.stats.inserted;
  }
}

}  // namespace

RefineResult refine_del2d(TriangleStore& m, const RefineOptions& opt) {
  RefineResult res;
  if (!(opt.size > 0) && !opt.size_at) {
    res.error = "refinement needs a positive size";
    return res;
  }
  Refiner r(m, opt, res);
  r.run();
  return res;
}

}  // namespace sm
