// FLANN-backed exact nearest-neighbour search. This is the only file of the
// project that includes FLANN. Two ideas make batches fast while keeping the
// answers exact:
// - queries are answered in Morton order, and each starts from the bound
//   given by the previous answer (distance from the query to the previous
//   query's nearest sample), so FLANN prunes from the start instead of first
//   descending to a far leaf;
// - far from the samples (mid-ocean points and a coastline), a k-d tree over
//   individual samples visits many cells. There the search runs on a second,
//   coarse tree over "buckets" (Morton runs of up to 64 samples with a centre
//   and a radius): a radius search over the centres finds every bucket that
//   may hold a point within the bound, and their points are scanned.
#include "field/knn.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <flann/flann.hpp>

#include "field/field.h"

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

/// Every point within sqrt(r2) of the query, up to `cap` of them; past the
/// cap the search is cut short (worstDist() < 0 prunes everything left).
class RadiusResult final : public flann::ResultSet<double> {
 public:
  RadiusResult(double r2, std::size_t cap, std::vector<std::uint32_t>& out)
      : r2_(r2), cap_(cap), out_(out) {}
  bool full() const override { return true; }
  void addPoint(double dist, std::size_t index) override {
    if (overflow_ || !(dist < r2_)) return;
    if (out_.size() == cap_) {
      overflow_ = true;
      return;
    }
    out_.push_back(static_cast<std::uint32_t>(index));
  }
  double worstDist() const override { return overflow_ ? -1.0 : r2_; }
  bool overflow() const { return overflow_; }

 private:
  double r2_;
  std::size_t cap_;
  std::vector<std::uint32_t>& out_;
  bool overflow_ = false;
};

/// Hands every point to a callback that sets the pruning bound.
class VisitResult final : public flann::ResultSet<double> {
 public:
  VisitResult(double bound2, const std::function<double(std::uint32_t, double)>& visit)
      : bound2_(bound2), visit_(visit) {}
  bool full() const override { return true; }
  void addPoint(double dist, std::size_t index) override {
    if (!(dist < bound2_)) return;
    bound2_ = std::min(bound2_, visit_(static_cast<std::uint32_t>(index), dist));
  }
  double worstDist() const override { return bound2_; }

 private:
  double bound2_;
  const std::function<double(std::uint32_t, double)>& visit_;
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
void radix_sort(std::vector<std::pair<std::uint64_t, std::uint32_t>>& keys) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> tmp(keys.size());
  for (int shift = 0; shift < 64; shift += 8) {
    std::size_t count[257] = {};
    for (const auto& k : keys) ++count[((k.first >> shift) & 0xff) + 1];
    if (count[((keys[0].first >> shift) & 0xff) + 1] == keys.size()) continue;
    for (int d = 0; d < 256; ++d) count[d + 1] += count[d];
    for (const auto& k : keys) tmp[count[(k.first >> shift) & 0xff]++] = k;
    keys.swap(tmp);
  }
}

/// Query order along a Morton curve of the batch's bounding box.
std::vector<std::uint32_t> morton_order(std::span<const Vec3> q) {
  Vec3 lo = q[0], hi = q[0];
  for (const Vec3& p : q) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double ext = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
  const double s = static_cast<double>((1u << 21) - 1) / ext;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    auto cell = [&](double c, double l) {
      return static_cast<std::uint64_t>(std::isfinite(c) ? (c - l) * s : 0.0);
    };
    keys[i] = {spread3(cell(q[i].x, lo.x)) | spread3(cell(q[i].y, lo.y)) << 1 |
                   spread3(cell(q[i].z, lo.z)) << 2,
               static_cast<std::uint32_t>(i)};
  }
  // A small batch (the 1D integrator's, along one curve: tens of points) is sorted as
  // pairs: the radix sort's eight passes over 257 counters would cost more than the
  // points. The order is the same, since the indices make every pair distinct.
  constexpr std::size_t kRadixFrom = 256;
  if (q.size() < kRadixFrom) {
    std::sort(keys.begin(), keys.end());
  } else {
    radix_sort(keys);
  }
  std::vector<std::uint32_t> order(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) order[i] = keys[i].second;
  return order;
}

/// Each thread's last answer on each tree: the seed of the first search of the thread's
/// next batch on that tree (batches are small, about 4.6 queries on the Arctic, and follow
/// each other along the mesh front, so an unbounded first search was a large share of the
/// descents). A size evaluation asks several trees in turn (the Distance fields,
/// ChannelWidth), so each tree has its slot: kLastSlots of them, by tree id (ids are given
/// in sequence, so the trees of one run do not share a slot unless there are more); a slot
/// another tree took just gives no seed. The seed only sets the starting bound: every search
/// keeps the nearest point, ties to the smallest index, whatever its bound, so the answers
/// do not depend on which thread asked what before (-nt 1 and -nt 2 give the same meshes).
struct LastAnswer {
  std::uint64_t tree_id = 0;  // 0: none (tree ids start at 1)
  std::size_t index = 0;
};
constexpr std::size_t kLastSlots = 16;
thread_local std::array<LastAnswer, kLastSlots> tl_last_answer;

std::uint64_t next_tree_id() {
  static std::atomic<std::uint64_t> counter{0};
  return counter.fetch_add(1, std::memory_order_relaxed) + 1;
}

}  // namespace

std::size_t KdTree::seed_of_batch() const {
  // Only for exact searches: with eps > 0 the seed may stand as the answer.
  const LastAnswer& last = tl_last_answer[id_ % kLastSlots];
  if (opts_.eps != 0 || last.tree_id != id_ || last.index >= points_.size())
    return std::numeric_limits<std::size_t>::max();
  return last.index;
}

void KdTree::keep_last_answer(std::size_t index) const {
  if (index < points_.size()) tl_last_answer[id_ % kLastSlots] = {id_, index};
}

struct KdTree::Impl {
  Impl(flann::Matrix<double> data, const KnnOptions& o)
      : tree(data, flann::KDTreeSingleIndexParams(o.leaf_size, /*reorder=*/true)) {}
  Tree tree;

  // Buckets: the samples in Morton order, cut into runs of at most kBucket
  // points (cut early where a run would get wider than the median width,
  // so Morton jumps do not make wide buckets). Bucket b holds
  // bx/by/bz/bid[start[b] .. start[b+1]) (coordinates and sample index),
  // with centre centre[b] and radius radius[b] <= tau; the coarse tree
  // indexes the centres. The far search looks at every bucket whose centre
  // is within (bound + tau), so a small tau (the largest radius) matters:
  // cutting at the median width rather than twice it took tau from 0.016
  // to 0.0078 and uniform queries from 0.95 to 1.02 M/s. 64 points and a
  // cut at 1x were the fastest of 32..128 and 0.7x..2x on world_i_A100.
  static constexpr std::size_t kBucket = 64;
  std::vector<double> bx, by, bz;
  std::vector<std::uint32_t> bid, start;
  std::vector<Vec3> centre;
  std::vector<double> radius;
  double tau = 0;
  std::unique_ptr<Tree> coarse;

  void build_buckets(const std::vector<Vec3>& pts);
};

KdTree::KdTree(std::vector<Vec3> points, KnnOptions opts)
    : points_(std::move(points)), opts_(opts), id_(next_tree_id()) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (points_.empty()) return;
  flann::Matrix<double> data(reinterpret_cast<double*>(points_.data()), points_.size(), 3);
  impl_ = std::make_unique<Impl>(data, opts_);
  impl_->tree.buildIndex();
  if (opts_.buckets && points_.size() >= 4096) impl_->build_buckets(points_);
}

void KdTree::Impl::build_buckets(const std::vector<Vec3>& pts) {
  const std::vector<std::uint32_t> order = morton_order(pts);
  // First pass: fixed runs, to learn the typical run width.
  std::vector<double> widths;
  for (std::size_t b = 0; b < order.size(); b += kBucket) {
    const std::size_t e = std::min(order.size(), b + kBucket);
    double w = 0;
    for (std::size_t k = b + 1; k < e; ++k) w = std::max(w, norm(pts[order[k]] - pts[order[b]]));
    widths.push_back(w);
  }
  std::nth_element(widths.begin(), widths.begin() + static_cast<long>(widths.size() / 2), widths.end());
  tau = std::max(widths[widths.size() / 2], 1e-300);
  // Second pass: runs cut where a point is farther than tau from the run's first.
  start.push_back(0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t first = start.back();
    if (k > first && (k - first == kBucket || norm(pts[order[k]] - pts[order[first]]) > tau))
      start.push_back(static_cast<std::uint32_t>(k));
  }
  start.push_back(static_cast<std::uint32_t>(order.size()));
  bx.resize(order.size());
  by.resize(order.size());
  bz.resize(order.size());
  bid.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Vec3& p = pts[order[k]];
    bx[k] = p.x, by[k] = p.y, bz[k] = p.z, bid[k] = order[k];
  }
  double rmax = 0;
  for (std::size_t b = 0; b + 1 < start.size(); ++b) {
    Vec3 c{};
    for (std::size_t k = start[b]; k < start[b + 1]; ++k) c += pts[order[k]];
    c = c / static_cast<double>(start[b + 1] - start[b]);
    double r = 0;
    for (std::size_t k = start[b]; k < start[b + 1]; ++k) r = std::max(r, norm(pts[order[k]] - c));
    centre.push_back(c);
    radius.push_back(r);
    rmax = std::max(rmax, r);
  }
  tau = rmax;
  flann::Matrix<double> cdata(reinterpret_cast<double*>(centre.data()), centre.size(), 3);
  coarse = std::make_unique<Tree>(cdata, flann::KDTreeSingleIndexParams(8, /*reorder=*/true));
  coarse->buildIndex();
}

KdTree::~KdTree() = default;

void KdTree::nearest(std::span<const Vec3> queries, std::span<double> dist,
                     std::span<std::uint32_t> index) const {
  const double none = std::numeric_limits<double>::infinity();
  nearest_capped(queries, std::span<const double>(&none, 1), dist, index);
}

void KdTree::nearest_below(std::span<const Vec3> queries, std::span<const double> limit,
                           std::span<double> dist) const {
  // The reach is a hair above the limit, so that a point at a distance up to the limit
  // is found whatever the rounding of its squared distance; no limit (or a non-positive
  // one) is no cut.
  constexpr double kReachMargin = 1e-9;
  std::vector<double> far2(limit.size());
  for (std::size_t i = 0; i < limit.size(); ++i) {
    const double reach = limit[i] * (1 + kReachMargin);
    far2[i] = limit[i] > 0 && std::isfinite(reach * reach) ? reach * reach : std::numeric_limits<double>::infinity();
  }
  nearest_capped(queries, far2, dist, {});
}

void KdTree::nearest_capped(std::span<const Vec3> queries, std::span<const double> far2_of,
                            std::span<double> dist, std::span<std::uint32_t> index) const {
  constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();
  if (!impl_) {
    for (double& d : dist) d = kMaxLc;
    for (std::uint32_t& i : index) i = std::numeric_limits<std::uint32_t>::max();
    return;
  }
  if (queries.empty()) return;
  constexpr std::size_t kMaxBuckets = 4096;  // past this, the fine search
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, opts_.eps);
  std::vector<std::uint32_t> order;
  if (opts_.sort_queries && queries.size() > 1) order = morton_order(queries);
  std::size_t prev = seed_of_batch();
  // The current query's cap (squared).
  double far2 = std::numeric_limits<double>::infinity();

  // One bounded search, seeded with the previous answer: (index, squared
  // distance). If nothing beats the seed (possible only with eps > 0, which
  // may prune the seed's own cell), the seed is the answer; it is within the
  // (1+eps) guarantee because everything pruned was at least that far.
  struct Found {
    std::size_t index;
    double d2;
  };
  // Without a cap (far2 infinite) every finite query finds its nearest point; with
  // one, a query that finds none within sqrt(far2) keeps the previous seed for the next.
  auto search = [&](const Vec3& q) -> Found {
    double bound = std::numeric_limits<double>::infinity();
    const std::size_t seed = prev;
    // Slightly inflated so the previous answer itself still qualifies.
    if (seed != NearestResult::kNone) bound = norm2(points_[seed] - q) * (1 + 1e-9) + 1e-300;
    const bool seeded = !(far2 < bound);  // also when the bound is NaN (a non-finite query)
    if (!seeded) bound = far2;
    NearestResult r(bound);
    impl_->tree.findNeighbors(r, &q.x, params);
    Found f{r.index(), r.best()};
    if (f.index == NearestResult::kNone && seeded && seed != NearestResult::kNone && std::isfinite(bound))
      f = {seed, norm2(points_[seed] - q)};
    if (f.index != NearestResult::kNone || std::isinf(far2)) prev = f.index;
    return f;
  };
  auto store = [&](std::size_t i, const Found& f) {
    if (f.index == NearestResult::kNone) {  // a non-finite query, or none within the cap
      const Vec3& q = queries[i];
      const bool beyond = std::isfinite(far2) && std::isfinite(q.x + q.y + q.z);
      dist[i] = beyond ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
      if (!index.empty()) index[i] = kNoIndex;
      return;
    }
    dist[i] = std::sqrt(f.d2);
    if (!index.empty()) index[i] = static_cast<std::uint32_t>(f.index);
  };

  // Within about one bucket radius of the samples the seeded fine search is
  // cheapest; farther out, the coarse tree over buckets.
  const Impl& im = *impl_;
  const bool two_level = im.coarse && opts_.eps == 0;
  std::vector<std::uint32_t> near;
  std::vector<std::pair<double, std::uint32_t>> gaps;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::size_t i = order.empty() ? k : order[k];
    const Vec3 q = queries[i];
    if (!far2_of.empty()) far2 = far2_of[far2_of.size() == 1 ? 0 : i];
    if (!two_level || prev == NearestResult::kNone) {
      store(i, search(q));
      continue;
    }
    double best2 = norm2(points_[prev] - q);
    std::size_t arg = prev;
    if (far2 < best2) best2 = far2, arg = NearestResult::kNone;  // the seed lies beyond the cap
    if (!(best2 >= im.tau * im.tau)) {  // also catches a NaN query
      store(i, search(q));
      continue;
    }
    // Every bucket that may hold a point closer than the seed.
    const double u = std::sqrt(best2) + im.tau;
    near.clear();
    RadiusResult rs(u * u * (1 + 1e-9), kMaxBuckets, near);
    im.coarse->findNeighbors(rs, &q.x, params);
    if (rs.overflow()) {
      store(i, search(q));
      continue;
    }
    // The bucket that may come closest is scanned first: its answer is
    // usually the nearest, and the bound it gives prunes most of the others.
    gaps.clear();
    std::size_t first = 0;
    for (std::uint32_t b : near) {
      const double gap = norm(im.centre[b] - q) - im.radius[b];
      if (gap > 0 && gap * gap > best2) continue;
      if (!gaps.empty() && gap < gaps[first].first) first = gaps.size();
      gaps.push_back({gap, b});
    }
    if (!gaps.empty()) std::swap(gaps[0], gaps[first]);
    for (const auto& [gap, b] : gaps) {
      if (gap > 0 && gap * gap > best2) continue;
      for (std::size_t m = im.start[b]; m < im.start[b + 1]; ++m) {
        const double dx = im.bx[m] - q.x, dy = im.by[m] - q.y, dz = im.bz[m] - q.z;
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < best2 || (d2 == best2 && im.bid[m] < arg)) best2 = d2, arg = im.bid[m];
      }
    }
    if (arg == NearestResult::kNone) {  // nothing within the cap
      dist[i] = std::numeric_limits<double>::infinity();
      if (!index.empty()) index[i] = kNoIndex;
      continue;
    }
    prev = arg;
    dist[i] = std::sqrt(best2);
    if (!index.empty()) index[i] = static_cast<std::uint32_t>(arg);
  }
  keep_last_answer(prev);
}

void KdTree::nearest_within(std::span<const Vec3> queries, std::span<const double> max_dist,
                            std::span<double> dist, std::span<std::uint32_t> index) const {
  constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();
  if (!impl_ || max_dist.empty()) {
    std::fill(dist.begin(), dist.end(), std::numeric_limits<double>::infinity());
    std::fill(index.begin(), index.end(), kNoIndex);
    return;
  }
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0);
  std::vector<std::uint32_t> order;
  if (opts_.sort_queries && queries.size() > 1) order = morton_order(queries);
  std::size_t prev = seed_of_batch();
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::size_t i = order.empty() ? k : order[k];
    const Vec3& q = queries[i];
    const double r = max_dist.size() == 1 ? max_dist[0] : max_dist[i];
    const double far2 = r > 0 ? r * r : 0;
    // Seeded with the previous answer when that is nearer than max_dist (inflated so
    // that it still qualifies itself).
    double bound = far2;
    const double seed2 = prev == NearestResult::kNone ? far2 : norm2(points_[prev] - q) * (1 + 1e-9) + 1e-300;
    const bool seeded = seed2 < far2;
    if (seeded) bound = seed2;
    std::size_t found = NearestResult::kNone;
    double d2 = 0;
    if (bound > 0) {
      NearestResult res(bound);
      impl_->tree.findNeighbors(res, &q.x, params);
      found = res.index();
      d2 = res.best();
    }
    if (found == NearestResult::kNone && seeded) {
      found = prev;
      d2 = norm2(points_[prev] - q);
    }
    if (found == NearestResult::kNone || !(d2 < far2)) {
      dist[i] = std::isfinite(q.x + q.y + q.z) ? std::numeric_limits<double>::infinity()
                                              : std::numeric_limits<double>::quiet_NaN();
      index[i] = kNoIndex;
      continue;
    }
    prev = found;
    dist[i] = std::sqrt(d2);
    index[i] = static_cast<std::uint32_t>(found);
  }
  keep_last_answer(prev);
}

void KdTree::visit_within(const Vec3& q, double bound2,
                          const std::function<double(std::uint32_t, double)>& visit) const {
  if (!impl_ || !(bound2 > 0)) return;
  VisitResult r(bound2, visit);
  impl_->tree.findNeighbors(r, &q.x, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED, 0));
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
