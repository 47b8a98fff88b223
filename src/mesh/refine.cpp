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
#include "mesh/insert.h"
#include "mesh/quality.h"

namespace sm {
namespace {

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
      : m_(m), opt_(opt), res_(res), ins_(m, opt.seed, &res.stats.predicates) {}
  void run();
  std::uint64_t walk_steps() const { return ins_.stats.walk_steps; }
  std::uint64_t cavity_triangles() const { return ins_.stats.cavity_triangles; }

 private:
  void consider(std::span<const std::uint32_t> tris);

  TriangleStore& m_;
  const RefineOptions& opt_;
  RefineResult& res_;
  PointInserter ins_;
  std::vector<std::uint32_t> queued_;  // per slot: priority bits when queued, 0 when not
  std::vector<Entry> heap_;
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
    if (ins_.insert_near(cc, TriId{t}) != InsertOutcome::Inserted) {
      ++res_.stats.rejected;
      continue;
    }
    ++res_.stats.inserted;
    if (queued_.size() < m_.num_slots()) queued_.resize(m_.num_slots(), 0);
    consider(ins_.created());
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
  res.stats.walk_steps = r.walk_steps();
  res.stats.cavity_triangles = r.cavity_triangles();
  return res;
}

}  // namespace sm
