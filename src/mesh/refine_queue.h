// What del2d (refine.cpp) and front2d (frontal.cpp) share: the option checks,
// a bucketed work list of triangles served largest priority first, batched
// size evaluation at circumcentres and the insertion bookkeeping.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mesh/insert.h"
#include "mesh/refine.h"
#include "mesh/triangulation.h"

namespace sm::detail {

/// The error for options no refinement can run with, or "".
std::string check_refine_options(const RefineOptions& opt);

/// Triangles waiting for an insertion, by priority (R^2 / h^2). A binary heap
/// of every queued triangle costs log n cache misses per pop at 10 million
/// triangles and serves them in an order scattered over the whole domain, so
/// each insertion misses the cache again on the mesh arrays. Here the
/// priority is cut into buckets of width 2^(1/32) (the float's exponent and top
/// mantissa bits) and each bucket is a stack: the largest bucket first, and
/// inside it the triangle queued last, which an insertion nearby has just
/// made. Entries are bare slots; an entry is stale when its slot is no longer
/// queued in that bucket (killed, rewritten or already served).
///
///   queued_[t] = bucket + 1 (0: not queued)    buckets_[b] = {t, t, t, ...} top ->
///
/// Deterministic: the order depends only on the sequence of pushes and pops.
class RefineQueue {
 public:
  static constexpr int kStepBits = 5;  // 32 buckets per factor 2 of R^2 / h^2
  static constexpr std::uint32_t kBuckets = 256u << kStepBits;

  RefineQueue() : buckets_(kBuckets) {}
  void grow(std::uint32_t slots) {
    if (queued_.size() < slots) queued_.resize(slots, 0);
  }
  /// Queues slot t (< grow's slots) with a positive finite priority.
  void push(std::uint32_t t, float priority) {
    const std::uint32_t b = bucket(priority);
    queued_[t] = static_cast<std::uint16_t>(b + 1);
    buckets_[b].push_back(t);
    if (b >= top_) top_ = b + 1;
  }
  bool queued(std::uint32_t t) const { return queued_[t] != 0; }
  /// Makes t's entry stale (t was re-sized or is being served).
  void drop(std::uint32_t t) { queued_[t] = 0; }
  /// The next live queued triangle (unqueued by the call), false when none is
  /// left. Counts pops and stale entries.
  bool pop(const TriangleStore& m, std::uint32_t& t) {
    while (top_ > 0) {
      std::vector<std::uint32_t>& st = buckets_[top_ - 1];
      if (st.empty()) {
        --top_;
        continue;
      }
      t = st.back();
      st.pop_back();
      ++pops;
      if (queued_[t] != top_ || !m.alive(TriId{t})) {
        ++stale;
        continue;
      }
      queued_[t] = 0;
      return true;
    }
    return false;
  }

  /// Follows TriangleStore::sort_spatially (new_slot[old], kNone for dead):
  /// stale entries go and each bucket is refilled in new slot order, so its
  /// stack serves the triangles along the curve (backwards).
  void renumber(const std::vector<std::uint32_t>& new_slot, std::uint32_t slots);

  std::uint64_t pops = 0, stale = 0;

 private:
  static std::uint32_t bucket(float priority) {
    std::uint32_t bits;
    static_assert(sizeof bits == sizeof priority);
    __builtin_memcpy(&bits, &priority, sizeof bits);
    return bits >> (23 - kStepBits);
  }

  std::vector<std::uint16_t> queued_;
  std::vector<std::vector<std::uint32_t>> buckets_;
  std::uint32_t top_ = 0;  // every bucket at or above top_ is empty
};

/// The state both refiners drive: the mesh, options, result, the point
/// inserter and the work list, plus scratch for batched size evaluation.
class RefineDriver {
 protected:
  RefineDriver(TriangleStore& m, const RefineOptions& opt, RefineResult& res)
      : m_(m), opt_(opt), res_(res), ins_(m, opt.seed, &res.stats.predicates) {
    ins_.keep_out_side = false;  // rebuilt once by finish()
    first_movable_ = m.num_vertices();
    next_sort_ = std::max(kFirstSort, 2 * m.num_triangles());
  }

  /// Sizes at the circumcentres of `tris` (pts_[i], h_[i]) then at the
  /// vertices `verts` (after them), from one size_at call. False, with the
  /// error recorded, when a size is not positive and finite.
  bool sample_sizes(std::span<const std::uint32_t> tris, std::span<const VertexId> verts = {});
  /// The size at p, in triangle t, as a vertex inserted there would get it: size_at (or
  /// size) at p, with vertex_size_at the smaller of that and the scaled barycentric
  /// interpolation of t's vertex sizes (as inserted() carries them).
  double size_at_point(Vec2 p, TriId t);
  /// The barycentric interpolation at p of the finite sizes `h` (per vertex) of the
  /// triangle c's corners (inf when none is).
  double vertex_interpolation(Vec2 p, const std::array<VertexId, 3>& c, const std::vector<double>& h) const;
  /// The live triangle slots, in order.
  std::vector<std::uint32_t> live_triangles() const;
  /// True, with the error recorded, when no vertex may be added any more.
  bool at_vertex_limit();
  /// Books a successful insertion: counts it and grows the work list over
  /// the slots it made.
  void inserted();
  /// Renumbers the mesh along a space-filling curve (sort_spatially; the
  /// input vertices keep their ids) once the triangle count has doubled
  /// since the last time, from kFirstSort triangles on. False when nothing
  /// was done; otherwise the caller remaps its own per-slot state.
  bool maybe_sort(std::vector<std::uint32_t>& new_slot, std::vector<std::uint32_t>& new_vertex);
  /// Rebuilds out_side and copies the counters of the work list and the
  /// inserter into the result.
  void finish();

  TriangleStore& m_;
  const RefineOptions& opt_;
  RefineResult& res_;
  PointInserter ins_;
  RefineQueue queue_;
  std::vector<Vec2> pts_;
  std::vector<std::pair<std::size_t, Vec2>> flat_;   // sample_sizes: flat triangles' circumcentres
  std::vector<double> h_;

 private:
  /// RefineOptions::vertex_size_at at every vertex not sized yet: those present on entry
  /// (inserted() sizes the others from their triangle; vertex ids only grow, and
  /// maybe_sort moves the sizes with their vertices). False on a size that is not
  /// positive (inf is "none").
  bool size_new_vertices();
  /// The mean of the finite vertex sizes of t (inf when none is).
  double vertex_mean(TriId t) const;

  std::vector<double> vsize_at_;   // per vertex: RefineOptions::vertex_size_at
  std::vector<Vec2> vpts_;
  std::vector<double> vh_, scale_;
  static constexpr std::uint32_t kFirstSort = 1u << 15;
  std::uint32_t first_movable_ = 0;
  std::uint32_t next_sort_ = kFirstSort;
};

}  // namespace sm::detail
