// Nearest-neighbour queries on 3D point sets: an exact k-d tree of our own, FLANN's for
// the approximate searches (the shore-proximity function f3 of paper
// section 3.1 uses ANN).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "base/vec.h"
#include "field/near_tree.h"

namespace sm::field {

struct KnnOptions {
  int leaf_size = 32;  ///< points per leaf of FLANN's k-d tree, built when eps > 0
  /// 0: exact. Otherwise the distance found is at most (1 + eps) times the true one.
  float eps = 0;
  /// Answer the queries of a batch in Morton (space-filling curve) order,
  /// each search starting with the bound given by the previous answer.
  bool sort_queries = true;
  /// Threads for the exact tree's build (field/near_tree.h): the same tree for any count.
  int threads = 1;
};

class KdTree {
 public:
  explicit KdTree(std::vector<Vec3> points, KnnOptions opts = {});
  ~KdTree();
  KdTree(const KdTree&) = delete;
  KdTree& operator=(const KdTree&) = delete;

  std::size_t size() const { return points_.size(); }
  const std::vector<Vec3>& points() const { return points_; }

  /// Euclidean (chord) distance from each query to its nearest point, and
  /// optionally that point's index. Thread-safe; an empty tree gives 1e22.
  void nearest(std::span<const Vec3> queries, std::span<double> dist,
               std::span<std::uint32_t> index = {}) const;

  /// As nearest(), but exact only up to `limit`: a query whose nearest point is
  /// farther may get +infinity instead (one with no point within limit (1 + 1e-9)
  /// does), and far queries stop early (a Threshold's Distance beyond its DistMax).
  /// `limit`: one value for every query, or one per query.
  void nearest_below(std::span<const Vec3> queries, std::span<const double> limit, std::span<double> dist) const;

  /// As nearest(), but only looking as far as max_dist (one value for every
  /// query, or one per query): a query with no point nearer gets dist = +infinity
  /// and index = UINT32_MAX. Far queries then cost one descent of the tree
  /// (ChannelWidth: beyond what could still lower the size nothing matters).
  void nearest_within(std::span<const Vec3> queries, std::span<const double> max_dist, std::span<double> dist,
                      std::span<std::uint32_t> index) const;

  /// Calls visit(index, squared distance) for the points within sqrt(bound2)
  /// of q (every such point unless pruned); visit returns the new squared
  /// bound, which may only shrink: cells beyond it are skipped. For searches
  /// whose criterion is not the plain distance but is bounded below by it
  /// (ChannelWidth's inscribed-ball width).
  /// A template, inlined into the leaves' loop (no std::function call a point).
  template <class Visit>
  void visit_within(const Vec3& q, double bound2, Visit&& visit) const {
    if (near_ && bound2 > 0) near_->visit(q, bound2, visit);
  }
  /// The same, entering only the cells where may_hold(box_dist2) is true (NearTree::visit).
  template <class Visit, class MayHold>
  void visit_within(const Vec3& q, double bound2, Visit&& visit, MayHold&& may_hold) const {
    if (near_ && bound2 > 0) near_->visit(q, bound2, visit, may_hold);
  }

 private:
  // nearest() with query i's search cut at squared distance far2_at(i) (infinite: no
  // cut); a query with no point nearer gets +infinity and UINT32_MAX. Defined and
  // instantiated in knn.cpp.
  template <class Far2>
  void nearest_capped(std::span<const Vec3> queries, const Far2& far2_at, std::span<double> dist,
                      std::span<std::uint32_t> index) const;

  struct Impl;
  std::vector<Vec3> points_;  // FLANN indexes this memory in place
  std::unique_ptr<NearTree> near_;  // ours: the exact searches and visit_within
  KnnOptions opts_;
  std::unique_ptr<Impl> impl_;
};

/// Brute-force oracle for tests.
void nearest_brute_force(std::span<const Vec3> points, std::span<const Vec3> queries,
                         std::span<double> dist, std::span<std::uint32_t> index = {});

}  // namespace sm::field
