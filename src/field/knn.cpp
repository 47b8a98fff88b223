// FLANN-backed exact k-d tree. This is the only file of the project that
// includes FLANN. Queries of a batch are answered in Morton order and each
// search is seeded with an upper bound from the previous answer (the distance
// from the query to the previous query's nearest point): FLANN then prunes
// every cell beyond that bound from the start instead of first descending to
// a far leaf, which makes queries far from the samples (mid-ocean points and
// a coastline) many times cheaper. Results stay exact.
#include "field/knn.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <flann/flann.hpp>

#include "field/field.h"

namespace sm::field {

namespace {

using Tree = flann::KDTreeSingleIndex<flann::L2_Simple<double>>;

/// One nearest neighbour, with an initial squared-distance bound.
class NearestResult final : public flann::ResultSet<double> {
 public:
  explicit NearestResult(double bound_sq) : worst_(bound_sq) {}
  bool full() const override { return true; }
  void addPoint(double dist, std::size_t index) override {
    if (dist < worst_ || index_ == kNone) {
      worst_ = dist;
      index_ = index;
    }
  }
  double worstDist() const override { return worst_; }
  std::size_t index() const { return index_; }

  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

 private:
  double worst_;
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
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> order(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) order[i] = keys[i].second;
  return order;
}

}  // namespace

struct KdTree::Impl {
  Impl(flann::Matrix<double> data, const KnnOptions& o)
      : tree(data, flann::KDTreeSingleIndexParams(o.leaf_size, /*reorder=*/true)) {}
  Tree tree;
};

KdTree::KdTree(std::vector<Vec3> points, KnnOptions opts) : points_(std::move(points)), opts_(opts) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (points_.empty()) return;
  flann::Matrix<double> data(reinterpret_cast<double*>(points_.data()), points_.size(), 3);
  impl_ = std::make_unique<Impl>(data, opts_);
  impl_->tree.buildIndex();
}

KdTree::~KdTree() = default;

void KdTree::nearest(std::span<const Vec3> queries, std::span<double> dist,
                     std::span<std::uint32_t> index) const {
  if (!impl_) {
    for (double& d : dist) d = kMaxLc;
    for (std::uint32_t& i : index) i = std::numeric_limits<std::uint32_t>::max();
    return;
  }
  if (queries.empty()) return;
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, opts_.eps);
  std::vector<std::uint32_t> order;
  if (opts_.sort_queries && queries.size() > 1) order = morton_order(queries);
  std::size_t prev = NearestResult::kNone;

  // One bounded search, seeded with the previous answer: (index, squared
  // distance). If nothing beats the seed (possible only with eps > 0, which
  // may prune the seed's own cell), the seed is the answer; it is within the
  // (1+eps) guarantee because everything pruned was at least that far.
  struct Found {
    std::size_t index;
    double d2;
  };
  auto search = [&](const Vec3& q) -> Found {
    double bound = std::numeric_limits<double>::infinity();
    const std::size_t seed = prev;
    // Slightly inflated so the previous answer itself still qualifies.
    if (seed != NearestResult::kNone) bound = norm2(points_[seed] - q) * (1 + 1e-9) + 1e-300;
    NearestResult r(bound);
    impl_->tree.findNeighbors(r, &q.x, params);
    Found f{r.index(), r.worstDist()};
    if (f.index == NearestResult::kNone && seed != NearestResult::kNone && std::isfinite(bound))
      f = {seed, norm2(points_[seed] - q)};
    prev = f.index;
    return f;
  };
  auto store = [&](std::size_t i, const Found& f) {
    if (f.index == NearestResult::kNone) {  // only for a non-finite query
      dist[i] = std::numeric_limits<double>::quiet_NaN();
      if (!index.empty()) index[i] = std::numeric_limits<std::uint32_t>::max();
      return;
    }
    dist[i] = std::sqrt(f.d2);
    if (!index.empty()) index[i] = static_cast<std::uint32_t>(f.index);
  };

  // Far from the samples a k-d tree search visits many cells. There, a group
  // of consecutive (Morton-close) queries with centre c and radius r shares
  // one candidate list: the nearest point of any query in the group lies
  // within d(c) + 2r of c. Each query then scans the list; the answer is
  // still exact. Groups grow while they stay small next to the distance to
  // the samples (estimated from the previous answer), so queries near the
  // samples keep the cheap single search.
  constexpr std::size_t kMaxGroup = 64, kMinGroup = 8, kMaxCandidates = 4096;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const bool grouping = opts_.eps == 0 && !order.empty();
  std::vector<std::uint32_t> cand;
  std::vector<double> cx, cy, cz;
  std::size_t k = 0;
  while (k < queries.size()) {
    auto at = [&](std::size_t j) -> std::size_t { return order.empty() ? k + j : order[k + j]; };
    std::size_t n = 1;
    if (grouping && prev != NearestResult::kNone) {
      const Vec3 q0 = queries[at(0)];
      const double reach = 0.25 * norm(points_[prev] - q0);
      while (n < kMaxGroup && k + n < queries.size() && norm(queries[at(n)] - q0) < reach) ++n;
    }
    bool grouped = false;
    if (n >= kMinGroup) {
      Vec3 c{};
      for (std::size_t j = 0; j < n; ++j) c += queries[at(j)];
      c = c / static_cast<double>(n);
      double r = 0;
      for (std::size_t j = 0; j < n; ++j) r = std::max(r, norm(queries[at(j)] - c));
      const double dc = std::sqrt(search(c).d2);
      if (std::isfinite(dc) && 2 * r < dc) {
        const double rr = (dc + 2 * r) * (1 + 1e-9) + 1e-300;
        cand.clear();
        RadiusResult rs(rr * rr, kMaxCandidates, cand);
        impl_->tree.findNeighbors(rs, &c.x, params);
        if (!rs.overflow() && !cand.empty()) {
          grouped = true;
          cx.resize(cand.size());
          cy.resize(cand.size());
          cz.resize(cand.size());
          for (std::size_t m = 0; m < cand.size(); ++m) {
            const Vec3& p = points_[cand[m]];
            cx[m] = p.x, cy[m] = p.y, cz[m] = p.z;
          }
          for (std::size_t j = 0; j < n; ++j) {
            const std::size_t i = at(j);
            const Vec3 q = queries[i];
            double best = kInf;
            std::size_t arg = 0;
            for (std::size_t m = 0; m < cand.size(); ++m) {
              const double dx = cx[m] - q.x, dy = cy[m] - q.y, dz = cz[m] - q.z;
              const double d2 = dx * dx + dy * dy + dz * dz;
              if (d2 < best) best = d2, arg = m;
            }
            dist[i] = std::sqrt(best);
            if (!index.empty()) index[i] = cand[arg];
            prev = cand[arg];
          }
        }
      }
    }
    if (!grouped)
      for (std::size_t j = 0; j < n; ++j) store(at(j), search(queries[at(j)]));
    k += n;
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
