// The exact nearest-point k-d tree of our own (KdTree's exact searches and visits,
// field/knn.h): split at the median of the widest side of each cell's box, leaves of at
// most kLeaf points whose coordinates lie together (x, y, z arrays in leaf order).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "base/vec.h"

namespace sm::field {

// A cell is skipped only when the squared distance from the query to its box is above
// the best so far: for a point inside the box every per-axis gap, computed in doubles,
// is at most the point's (rounding is monotone), so the box's figure is never above any
// of its points' squared distance, and a point at exactly the best distance with a
// smaller index is still seen.
//
//   node k: box lo[3], hi[3]; a leaf holds x/y/z/id[begin .. end); an inner node's two
//   children are nodes child and child + 1, split on `axis`: every coordinate of the
//   first is at most the second's smallest (its lo[axis]).
class NearTree {
 public:
  /// Built on `threads` threads below its top levels: the same tree for every count.
  explicit NearTree(std::span<const Vec3> pts, int threads = 1);

  /// Lowers (best2, best) to the nearest point's squared distance and index when it is
  /// nearer, or as near with a smaller index; `best` = kNoTie lets only a strictly nearer
  /// point in (a cap, not a candidate). Descends from the root, the nearer child first.
  void search(const Vec3& q, double& best2, std::uint32_t& best) const;

  /// The same answer, searched from the leaf whose cell holds q outwards: down the
  /// splits to that leaf (one comparison a level), then back up, each level's other
  /// child searched unless its box is beyond the best, and the climb stopped where every
  /// point outside the cell reached is beyond the best (the batches' queries, seeded
  /// with a near candidate, mostly stop a few levels above their leaf).
  void search_up(const Vec3& q, double& best2, std::uint32_t& best) const;

  /// Calls visit(index, squared distance) for each point nearer than sqrt(bound2), in the
  /// tree's order; bound2 becomes min(bound2, what visit returns), and cells beyond it
  /// are skipped. A template, so that the visit is inlined into the leaves' loop
  /// (ChannelWidth's set-up makes one per coast sample).
  template <class Visit>
  void visit(const Vec3& q, double bound2, Visit&& fn) const {
    visit(q, bound2, fn, [](const auto&) { return true; });
  }

  /// As visit(), but a cell is entered only where may_hold(box_dist2) is true as well:
  /// box_dist2(c) is the squared distance from c to the cell's box (computed as the
  /// search's own bound is). For a criterion whose points lie in a region smaller than
  /// the ball, which may shrink as visit lowers the bound: ChannelWidth's tangent balls.
  template <class Visit, class MayHold>
  void visit(const Vec3& q, double bound2, Visit&& fn, MayHold&& may_hold) const {
    if (nodes_.empty()) return;
    walk(
        q, 0, box2(nodes_[0], q), bound2,
        [&](std::uint32_t m, double d2) {
          if (d2 < bound2) bound2 = std::min(bound2, static_cast<double>(fn(id_[m], d2)));
        },
        [&](const Node& nd) { return may_hold([&nd](const Vec3& c) { return box2(nd, c); }); });
  }

  /// The "index" that no point's index is below: a tie with it never wins.
  static constexpr std::uint32_t kNoTie = 0;

 private:
  static constexpr std::uint32_t kLeaf = 8;
  // Each level halves the points, so the depth stays below log2(2^32 / kLeaf) + 1.
  static constexpr std::size_t kMaxDepth = 32;
  struct Node {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    std::uint32_t begin = 0, end = 0;
    std::uint32_t child = 0;  // 0: a leaf
    std::uint32_t axis = 0;   // the split's axis (inner nodes)
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

  /// The descent search and visit share, over node `from`'s subtree whose box is at
  /// `bound` from q: the nearer child first, a cell entered only while its box is no
  /// farther than `limit` (and `enter(node)` holds), which `leaf(slot, squared distance)`
  /// may lower for each point of a leaf entered. A stack of kMaxDepth pending cells
  /// bounds it.
  template <class Leaf>
  void walk(const Vec3& q, std::uint32_t from, double bound, const double& limit, Leaf&& leaf) const {
    walk(q, from, bound, limit, leaf, [](const Node&) { return true; });
  }
  template <class Leaf, class Enter>
  void walk(const Vec3& q, std::uint32_t from, double bound, const double& limit, Leaf&& leaf,
            Enter&& enter) const {
    // Not initialised (a std::array of pairs would be zeroed: 512 bytes a call).
    struct Pending {
      std::uint32_t node;
      double bound;
    };
    Pending stack[kMaxDepth];
    std::size_t top = 0;
    std::uint32_t k = from;
    for (;;) {
      if (bound <= limit && enter(nodes_[k])) {  // false for a NaN query
        const Node& nd = nodes_[k];
        if (nd.child != 0) {
          const double b1 = box2(nodes_[nd.child], q), b2 = box2(nodes_[nd.child + 1], q);
          const bool first_nearer = b1 <= b2;
          stack[top++] = first_nearer ? Pending{nd.child + 1, b2} : Pending{nd.child, b1};
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
      k = stack[top].node;
      bound = stack[top].bound;
    }
  }

  // A subtree left for the threads: node k over ids[begin, end) at `depth`, its
  // descendants numbered from `next` on.
  struct Subtree {
    std::uint32_t k, begin, end;
    std::size_t depth;
    std::uint32_t next;
  };
  // Node k over ids[begin, end): its box, and below it, when it has more than kLeaf
  // points, its two children numbered `next` and next + 1 (next then past them and their
  // subtrees: the order of one depth-first build). With `deferred`, a node at
  // kSubtreeDepth is left there as a Subtree instead.
  void build(std::span<const Vec3> pts, std::vector<std::uint32_t>& ids, std::uint32_t k, std::uint32_t begin,
             std::uint32_t end, std::size_t depth, std::uint32_t& next, std::vector<Subtree>* deferred);
  // The nodes a node over `count` points at `depth` has below it (as build makes them).
  static std::uint32_t descendants(std::uint32_t count, std::size_t depth);
  // Subtrees are built on the threads from this depth down (8 of them).
  static constexpr std::size_t kSubtreeDepth = 3;

  std::vector<Node> nodes_;
  std::vector<double> x_, y_, z_;
  std::vector<std::uint32_t> id_;
};

}  // namespace sm::field
