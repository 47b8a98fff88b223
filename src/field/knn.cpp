// FLANN-backed k-d tree. This is the only file of the project that includes
// FLANN; FLANN returns squared L2 distances, converted here.
#include "field/knn.h"

#include <cmath>
#include <limits>

#include <flann/flann.hpp>

#include "field/field.h"

namespace sm::field {

struct KdTree::Impl {
  explicit Impl(flann::Matrix<double> data, int leaf)
      : index(data, flann::KDTreeSingleIndexParams(leaf, /*reorder=*/true)) {}
  flann::Index<flann::L2_Simple<double>> index;
};

KdTree::KdTree(std::vector<Vec3> points, KnnOptions opts) : points_(std::move(points)), opts_(opts) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  if (points_.empty()) return;
  flann::Matrix<double> data(reinterpret_cast<double*>(points_.data()), points_.size(), 3);
  impl_ = std::make_unique<Impl>(data, opts_.leaf_size);
  impl_->index.buildIndex();
}

KdTree::~KdTree() = default;

void KdTree::nearest(std::span<const Vec3> queries, std::span<double> dist,
                     std::span<std::uint32_t> index) const {
  if (!impl_) {
    for (double& d : dist) d = kMaxLc;
    for (std::uint32_t& i : index) i = std::numeric_limits<std::uint32_t>::max();
    return;
  }
  // FLANN takes non-const matrices; it does not write to the queries.
  constexpr std::size_t kChunk = 4096;
  std::vector<std::size_t> idx(std::min(kChunk, queries.size()));
  flann::SearchParams params(opts_.checks == -1 ? flann::FLANN_CHECKS_UNLIMITED : opts_.checks);
  params.cores = 1;
  for (std::size_t b = 0; b < queries.size(); b += kChunk) {
    const std::size_t n = std::min(kChunk, queries.size() - b);
    flann::Matrix<double> q(const_cast<double*>(&queries[b].x), n, 3);
    flann::Matrix<std::size_t> mi(idx.data(), n, 1);
    flann::Matrix<double> md(dist.data() + b, n, 1);
    impl_->index.knnSearch(q, mi, md, 1, params);
    for (std::size_t i = 0; i < n; ++i) {
      dist[b + i] = std::sqrt(dist[b + i]);
      if (!index.empty()) index[b + i] = static_cast<std::uint32_t>(idx[i]);
    }
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
