// Exact nearest-neighbour search and visits over a k-d tree of our own, and FLANN's k-d
// tree for the approximate searches (the only FLANN user of the project). Batches
// are answered in Morton (space-filling curve) order, each query starting with the
// previous answer as the candidate to beat, so that most cells are skipped from the
// start; the tie rule (of several points at the same distance, the smallest index) makes
// every answer independent of that order.
#include "field/knn.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <flann/flann.hpp>

#include "field/field.h"
#include "field/near_tree.h"

namespace sm::field {

namespace {

using Tree = flann::KDTreeSingleIndex<flann::L2_Simple<double>>;

/// The next double above a squared distance: std::nextafter(x, +infinity), which is one
/// step of the bit pattern for a finite x >= 0 (the library call costs ten times more,
/// and the searches make one per better point found).
inline double next_up(double x) {
  if (!(x >= 0) || std::isinf(x)) return std::nextafter(x, std::numeric_limits<double>::infinity());
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) + 1);
}

/// One nearest neighbour, with an initial squared-distance bound. Of several
/// points at exactly the same distance the one with the smallest index wins,
/// whatever the order of the visit (the seed of the search depends on the other
/// queries of the batch): worstDist() is a hair above the best distance, so that
/// FLANN still hands over points at that distance (its leaves test dist < worst).
class NearestResult final : public flann::ResultSet<double> {
 public:
  explicit NearestResult(double bound_sq) : worst_(bound_sq) {}
  bool full() const override { return true; }
  void addPoint(double dist, std::size_t index) override {
    if (dist < worst_ || index_ == kNone || (dist == worst_ && index < index_)) {
      worst_ = dist;
      index_ = index;
      bound_ = next_up(worst_);
    }
  }
  double worstDist() const override { return index_ == kNone ? worst_ : bound_; }
  std::size_t index() const { return index_; }
  /// The best squared distance (the bound while nothing was found).
  double best() const { return worst_; }

  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

 private:
  double worst_;
  double bound_ = 0;
  std::size_t index_ = kNone;
};

/// Spreads the low 21 bits of v to every third bit.
std::uint64_t spread3(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

// LSD radix sort of (key, index) pairs by key, 8 bits a pass (stable, so equal keys stay
// in index order, as a sort of the pairs would give); passes where every key has the same
// digit are skipped. Several times faster than std::sort on large batches.
// A query's Morton key and its index; no default member values, so that a stack array of
// them is not zeroed first.
struct MortonKey {
  std::uint64_t key;
  std::uint32_t index;
  friend bool operator<(const MortonKey& a, const MortonKey& b) {
    return a.key != b.key ? a.key < b.key : a.index < b.index;
  }
};

void radix_sort(std::vector<MortonKey>& keys) {
  std::vector<MortonKey> tmp(keys.size());
  for (int shift = 0; shift < 64; shift += 8) {
    std::size_t count[257] = {};
    for (const auto& k : keys) ++count[((k.key >> shift) & 0xff) + 1];
    if (count[((keys[0].key >> shift) & 0xff) + 1] == keys.size()) continue;
    for (int d = 0; d < 256; ++d) count[d + 1] += count[d];
    for (const auto& k : keys) tmp[count[(k.key >> shift) & 0xff]++] = k;
    keys.swap(tmp);
  }
}

/// The Morton key of each query: its cell on a 2^21 grid of the batch's bounding box per
/// axis, the three cell numbers' bits interleaved.
void morton_keys(std::span<const Vec3> q, MortonKey* keys) {
  Vec3 lo = q[0], hi = q[0];
  for (const Vec3& p : q) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double ext = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
  const double s = static_cast<double>((1u << 21) - 1) / ext;
  for (std::size_t i = 0; i < q.size(); ++i) {
    auto cell = [&](double c, double l) {
      return static_cast<std::uint64_t>(std::isfinite(c) ? (c - l) * s : 0.0);
    };
    keys[i] = {spread3(cell(q[i].x, lo.x)) | spread3(cell(q[i].y, lo.y)) << 1 |
                   spread3(cell(q[i].z, lo.z)) << 2,
               static_cast<std::uint32_t>(i)};
  }
}

// A batch of at most this many queries is ordered on the stack and sorted as pairs (the
// 2D refiners' batches, the circumcentres of one insertion's triangles, have about 15:
// a heap allocation each would cost more than their sort), a larger one on the heap by
// the radix sort, whose eight passes over 257 counters pay only for many points. Both
// give the same order, since the indices make every pair distinct.
constexpr std::size_t kSmallBatch = 256;

// Below this many queries a batch is answered in its own order: the refiners' batches of
// about 15 (one insertion's new triangles around its vertex, each next to the one before)
// are in a near order already, and their Morton keys and sort cost more than they save.
constexpr std::size_t kSortFrom = 32;

/// Query order along a Morton curve of the batch's bounding box: order[k] is the k-th
/// query's index. Stack memory for a small batch, else `heap`'s (resized).
std::span<const std::uint32_t> morton_order(std::span<const Vec3> q,
                                            std::array<std::uint32_t, kSmallBatch>& small,
                                            std::vector<std::uint32_t>& heap) {
  if (q.size() <= kSmallBatch) {
    MortonKey keys[kSmallBatch];  // not initialised: the batch's part written first
    morton_keys(q, keys);
    std::sort(keys, keys + q.size());
    for (std::size_t i = 0; i < q.size(); ++i) small[i] = keys[i].index;
    return {small.data(), q.size()};
  }
  std::vector<MortonKey> keys(q.size());
  morton_keys(q, keys.data());
  radix_sort(keys);
  heap.resize(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) heap[i] = keys[i].index;
  return heap;
}

// The order a batch's queries are answered in: along a Morton curve (morton_order) from
// kSortFrom queries on when sorting is asked for, else the batch's own. Holds the order's
// memory, so it is neither copied nor moved.
class QueryOrder {
 public:
  QueryOrder(std::span<const Vec3> q, bool sort) {
    if (sort && q.size() >= kSortFrom) order_ = morton_order(q, small_, heap_);
  }
  QueryOrder(const QueryOrder&) = delete;
  QueryOrder& operator=(const QueryOrder&) = delete;

  /// The index of the k-th query answered.
  std::size_t operator[](std::size_t k) const { return order_.empty() ? k : order_[k]; }

 private:
  std::array<std::uint32_t, kSmallBatch> small_;  // not initialised: trivial elements
  std::vector<std::uint32_t> heap_;
  std::span<const std::uint32_t> order_;
};

}  // namespace

struct KdTree::Impl {
  std::unique_ptr<Tree> flann;  // FLANN's, built only for approximate searches (eps > 0)
};

KdTree::KdTree(std::vector<Vec3> points, KnnOptions opts) : points_(std::move(points)), opts_(opts) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (points_.empty()) return;
  near_ = std::make_unique<NearTree>(points_, opts_.threads);
  impl_ = std::make_unique<Impl>();
  if (opts_.eps > 0) {
    flann::Matrix<double> data(reinterpret_cast<double*>(points_.data()), points_.size(), 3);
    impl_->flann = std::make_unique<Tree>(data, flann::KDTreeSingleIndexParams(opts_.leaf_size, /*reorder=*/true));
    impl_->flann->buildIndex();
  }
}

KdTree::~KdTree() = default;

void KdTree::nearest(std::span<const Vec3> queries, std::span<double> dist,
                     std::span<std::uint32_t> index) const {
  nearest_capped(queries, [](std::size_t) { return std::numeric_limits<double>::infinity(); }, dist, index);
}

void KdTree::nearest_below(std::span<const Vec3> queries, std::span<const double> limit,
                           std::span<double> dist) const {
  // The reach is a hair above the limit, so that a point at a distance up to the limit
  // is found whatever the rounding of its squared distance; no limit (or a non-positive
  // one) is no cut. Computed per query (no array of them: a heap allocation a batch).
  constexpr double kReachMargin = 1e-9;
  const auto far2_at = [limit](std::size_t i) {
    const double l = limit[limit.size() == 1 ? 0 : i];
    const double reach = l * (1 + kReachMargin);
    return l > 0 && std::isfinite(reach * reach) ? reach * reach : std::numeric_limits<double>::infinity();
  };
  if (limit.empty()) {
    nearest(queries, dist);
    return;
  }
  nearest_capped(queries, far2_at, dist, {});
}

template <class Far2>
void KdTree::nearest_capped(std::span<const Vec3> queries, const Far2& far2_at, std::span<double> dist,
                            std::span<std::uint32_t> index) const {
  constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();
  if (!impl_) {
    for (double& d : dist) d = kMaxLc;
    for (std::uint32_t& i : index) i = kNoIndex;
    return;
  }
  if (queries.empty()) return;
  const QueryOrder order(queries, opts_.sort_queries);
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, opts_.eps);
  std::uint32_t prev = kNoIndex;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::size_t i = order[k];
    const Vec3& q = queries[i];
    const double far2 = far2_at(i);
    double best2 = far2;
    std::uint32_t best = NearTree::kNoTie;
    bool found = false;
    if (!impl_->flann) {
      // The previous query's answer is the candidate to beat when it lies within the cap:
      // in Morton order it is usually near, and most cells are skipped from the start.
      if (prev != kNoIndex) {
        const double seed2 = norm2(points_[prev] - q);
        if (seed2 < far2) best2 = seed2, best = prev;
      }
      near_->search_up(q, best2, best);
      found = best2 < far2;
    } else {
      // A (1 + eps)-approximate search: FLANN's.
      NearestResult r(far2);
      impl_->flann->findNeighbors(r, &q.x, params);
      found = r.index() != NearestResult::kNone;
      if (found) best2 = r.best(), best = static_cast<std::uint32_t>(r.index());
    }
    if (!found) {  // a non-finite query, or none within the cap
      const bool beyond = std::isfinite(far2) && std::isfinite(q.x + q.y + q.z);
      dist[i] = beyond ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
      if (!index.empty()) index[i] = kNoIndex;
      continue;
    }
    prev = best;
    dist[i] = std::sqrt(best2);
    if (!index.empty()) index[i] = best;
  }
}

void KdTree::nearest_within(std::span<const Vec3> queries, std::span<const double> max_dist,
                            std::span<double> dist, std::span<std::uint32_t> index) const {
  constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();
  if (!impl_ || max_dist.empty()) {
    std::fill(dist.begin(), dist.end(), std::numeric_limits<double>::infinity());
    std::fill(index.begin(), index.end(), kNoIndex);
    return;
  }
  const QueryOrder order(queries, opts_.sort_queries);
  std::uint32_t prev = kNoIndex;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::size_t i = order[k];
    const Vec3& q = queries[i];
    const double r = max_dist.size() == 1 ? max_dist[0] : max_dist[i];
    const double far2 = r > 0 ? r * r : 0;
    double best2 = far2;
    std::uint32_t best = NearTree::kNoTie;
    if (prev != kNoIndex) {
      const double seed2 = norm2(points_[prev] - q);
      if (seed2 < far2) best2 = seed2, best = prev;
    }
    near_->search_up(q, best2, best);
    if (!(best2 < far2)) {
      dist[i] = std::isfinite(q.x + q.y + q.z) ? std::numeric_limits<double>::infinity()
                                              : std::numeric_limits<double>::quiet_NaN();
      index[i] = kNoIndex;
      continue;
    }
    prev = best;
    dist[i] = std::sqrt(best2);
    index[i] = best;
  }
}

void nearest_brute_force(std::span<const Vec3> points, std::span<const Vec3> queries,
                         std::span<double> dist, std::span<std::uint32_t> index) {
  for (std::size_t i = 0; i < queries.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t arg = std::numeric_limits<std::uint32_t>::max();
    for (std::size_t j = 0; j < points.size(); ++j) {
      const double d = norm2(points[j] - queries[i]);
      if (d < best) {
        best = d;
        arg = static_cast<std::uint32_t>(j);
      }
    }
    dist[i] = points.empty() ? kMaxLc : std::sqrt(best);
    if (!index.empty()) index[i] = arg;
  }
}

}  // namespace sm::field
