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

// The exact nearest-point tree of our own: a k-d tree over the points, split at the
// median of the widest side of each cell's box, leaves of at most kNearLeaf points
// whose coordinates lie together (x, y, z arrays in leaf order). A cell is skipped only
// when the squared distance from the query to its box is above the best so far: for a
// point inside the box every per-axis gap, computed in doubles, is at most the point's
// (rounding is monotone), so the box's figure is never above any of its points' squared
// distance, and a point at exactly the best distance with a smaller index is still seen.
//
//   node k: box lo[3], hi[3]; a leaf holds x/y/z/id[begin .. end); an inner node's two
//   children are nodes child and child + 1 (nearer one searched first)
class NearTree {
 public:
  explicit NearTree(const std::vector<Vec3>& pts) {
    const std::size_t n = pts.size();
    std::vector<std::uint32_t> ids(n);
    for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::uint32_t>(i);
    nodes_.reserve(2 * (n / kNearLeaf + 1));
    nodes_.push_back({});
    build(pts, ids, 0, 0, static_cast<std::uint32_t>(n), 0);
    x_.resize(n), y_.resize(n), z_.resize(n), id_ = ids;
    for (std::size_t k = 0; k < n; ++k) x_[k] = pts[ids[k]].x, y_[k] = pts[ids[k]].y, z_[k] = pts[ids[k]].z;
  }

  /// Lowers (best2, best) to the nearest point's squared distance and index when it is
  /// nearer, or as near with a smaller index; `best` = kNoTie lets only a strictly nearer
  /// point in (a cap, not a candidate).
  void search(const Vec3& q, double& best2, std::uint32_t& best) const {
    walk(q, best2, [&](std::uint32_t m, double d2) {
      if (d2 < best2 || (d2 == best2 && id_[m] < best)) best2 = d2, best = id_[m];
    });
  }

  /// Calls visit(index, squared distance) for each point nearer than sqrt(bound2), in the
  /// tree's order; bound2 becomes min(bound2, what visit returns), and cells beyond it
  /// are skipped.
  void visit(const Vec3& q, double bound2, const std::function<double(std::uint32_t, double)>& fn) const {
    walk(q, bound2, [&](std::uint32_t m, double d2) {
      if (d2 < bound2) bound2 = std::min(bound2, fn(id_[m], d2));
    });
  }

  /// The "index" that no point's index is below: a tie with it never wins.
  static constexpr std::uint32_t kNoTie = 0;

 private:
  /// The descent search and visit share: the nearer child first, a cell entered only while
  /// its box is no farther than `limit`, which `leaf(slot, squared distance)` may lower for
  /// each point of a leaf entered. A stack of kMaxDepth pending cells bounds it.
  template <class Leaf>
  void walk(const Vec3& q, const double& limit, Leaf&& leaf) const {
    std::array<std::pair<std::uint32_t, double>, kMaxDepth> stack;
    std::size_t top = 0;
    std::uint32_t k = 0;
    double bound = box2(nodes_[0], q);
    for (;;) {
      if (bound <= limit) {  // false for a NaN query
        const Node& nd = nodes_[k];
        if (nd.child != 0) {
          const double b1 = box2(nodes_[nd.child], q), b2 = box2(nodes_[nd.child + 1], q);
          const bool first_nearer = b1 <= b2;
          stack[top++] = first_nearer ? std::pair{nd.child + 1, b2} : std::pair{nd.child, b1};
          k = first_nearer ? nd.child : nd.child + 1;
          bound = first_nearer ? b1 : b2;
          continue;
        }
        for (std::uint32_t m = nd.begin; m < nd.end; ++m) {
          const double dx = x_[m] - q.x, dy = y_[m] - q.y, dz = z_[m] - q.z;
          leaf(m, dx * dx + dy * dy + dz * dz);
        }
      }
      if (top == 0) return;
      --top;
      k = stack[top].first;
      bound = stack[top].second;
    }
  }

  static constexpr std::uint32_t kNearLeaf = 8;
  // Each level halves the points, so the depth stays below log2(2^32 / kNearLeaf) + 1.
  static constexpr std::size_t kMaxDepth = 32;
  struct Node {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    std::uint32_t begin = 0, end = 0;
    std::uint32_t child = 0;  // 0: a leaf
  };

  static double box2(const Node& nd, const Vec3& q) {
    const double c[3] = {q.x, q.y, q.z};
    double s = 0;
    for (int a = 0; a < 3; ++a) {
      const double g = c[a] < nd.lo[a] ? nd.lo[a] - c[a] : c[a] > nd.hi[a] ? c[a] - nd.hi[a] : 0.0;
      s += g * g;
    }
    return s;
  }

  void build(const std::vector<Vec3>& pts, std::vector<std::uint32_t>& ids, std::uint32_t k, std::uint32_t begin,
             std::uint32_t end, std::size_t depth) {
    Node nd;
    nd.begin = begin, nd.end = end;
    for (int a = 0; a < 3; ++a) nd.lo[a] = std::numeric_limits<double>::infinity(), nd.hi[a] = -nd.lo[a];
    for (std::uint32_t m = begin; m < end; ++m) {
      const Vec3& p = pts[ids[m]];
      const double c[3] = {p.x, p.y, p.z};
      for (int a = 0; a < 3; ++a) nd.lo[a] = std::min(nd.lo[a], c[a]), nd.hi[a] = std::max(nd.hi[a], c[a]);
    }
    if (end - begin > kNearLeaf && depth + 1 < kMaxDepth) {
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (nd.hi[a] - nd.lo[a] > nd.hi[axis] - nd.lo[axis]) axis = a;
      // Point i's coordinate on the axis: the axis-th double of pts[i] (Vec3 is three doubles).
      const double* coord = &pts[0].x + axis;
      const std::uint32_t mid = begin + (end - begin) / 2;
      std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end,
                       [coord](std::uint32_t i, std::uint32_t j) { return coord[3 * i] < coord[3 * j]; });
      nd.child = static_cast<std::uint32_t>(nodes_.size());
      nodes_.push_back({});
      nodes_.push_back({});
      nodes_[k] = nd;
      build(pts, ids, nd.child, begin, mid, depth + 1);
      build(pts, ids, nd.child + 1, mid, end, depth + 1);
      return;
    }
    nodes_[k] = nd;
  }

  std::vector<Node> nodes_;
  std::vector<double> x_, y_, z_;
  std::vector<std::uint32_t> id_;
};

}  // namespace

struct KdTree::Impl {
  explicit Impl(const std::vector<Vec3>& pts) : near(pts) {}
  NearTree near;               // ours: the exact searches and visit_within
  std::unique_ptr<Tree> flann;  // FLANN's, built only for approximate searches (eps > 0)
};

KdTree::KdTree(std::vector<Vec3> points, KnnOptions opts) : points_(std::move(points)), opts_(opts) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (points_.empty()) return;
  impl_ = std::make_unique<Impl>(points_);
  if (opts_.eps > 0) {
    flann::Matrix<double> data(reinterpret_cast<double*>(points_.data()), points_.size(), 3);
    impl_->flann = std::make_unique<Tree>(data, flann::KDTreeSingleIndexParams(opts_.leaf_size, /*reorder=*/true));
    impl_->flann->buildIndex();
  }
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
    for (std::uint32_t& i : index) i = kNoIndex;
    return;
  }
  if (queries.empty()) return;
  std::vector<std::uint32_t> order;
  if (opts_.sort_queries && queries.size() > 1) order = morton_order(queries);
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, opts_.eps);
  std::uint32_t prev = kNoIndex;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::size_t i = order.empty() ? k : order[k];
    const Vec3& q = queries[i];
    const double far2 =
        far2_of.empty() ? std::numeric_limits<double>::infinity() : far2_of[far2_of.size() == 1 ? 0 : i];
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
      impl_->near.search(q, best2, best);
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
  std::vector<std::uint32_t> order;
  if (opts_.sort_queries && queries.size() > 1) order = morton_order(queries);
  std::uint32_t prev = kNoIndex;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::size_t i = order.empty() ? k : order[k];
    const Vec3& q = queries[i];
    const double r = max_dist.size() == 1 ? max_dist[0] : max_dist[i];
    const double far2 = r > 0 ? r * r : 0;
    double best2 = far2;
    std::uint32_t best = NearTree::kNoTie;
    if (prev != kNoIndex) {
      const double seed2 = norm2(points_[prev] - q);
      if (seed2 < far2) best2 = seed2, best = prev;
    }
    impl_->near.search(q, best2, best);
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

void KdTree::visit_within(const Vec3& q, double bound2,
                          const std::function<double(std::uint32_t, double)>& visit) const {
  if (!impl_ || !(bound2 > 0)) return;
  impl_->near.visit(q, bound2, visit);
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
