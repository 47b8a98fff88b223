// The kept points of passage closing's rings (passages.cpp) as ropes: each ring's points in
// ring order held by an implicit treap (a binary tree ordered by position, balanced by a
// fixed pseudo-random priority per tree node), so that a cut splits a ring and a join
// concatenates two in O(log n) instead of copying them (a continent cut once per inlet was
// cuts x ring size). Each tree node also sums its subtree's segment metres and keeps its
// lowest point, so that a ring's orientation and the metres between two positions need no
// pass over the ring either; and its subtree's (u,v) segment lengths and shoelace terms,
// from which a ring's mean width is bounded in O(1) (coast/mean_width.h). (Not the
// subtree's first and last points nor its point sum: with them, 40 bytes more a point made
// the 3 km import's peak 2.3% higher, every kept point being in a rope there.)
//
//   rope (positions 0..6):  a b c d e f g         its tree:        d
//                                                                 /   \   .
//   each tree node: its point, the metres of the                 b     f
//   segment to the next point, and of its subtree               / \   / \  .
//   the size, the metres' sum and the lowest point             a   c e   g
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "base/vec.h"

namespace sm::coast {

class KeptRopes {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  /// A rope is its root tree node (kNone: empty); a tree node is a point of one rope.
  using Rope = std::uint32_t;
  using TreeNode = std::uint32_t;
  /// One point: the caller's id for it, its (u,v) point and the metres of its segment to
  /// the next point of its ring.
  struct Item {
    std::uint32_t id;
    Vec2 uv;
    double metres;
  };

  /// A rope of `items` in order, in O(n).
  Rope make(std::span<const Item> items);
  std::size_t size(Rope r) const { return r == kNone ? 0 : nodes_[r].size; }
  /// The tree node at position j (j < size(r)).
  TreeNode at(Rope r, std::size_t j) const;
  std::uint32_t id(TreeNode t) const { return nodes_[t].id; }
  Vec2 uv(TreeNode t) const { return nodes_[t].uv; }
  double metres(TreeNode t) const { return nodes_[t].metres; }
  /// Position of t in its rope, and the rope (its root).
  std::size_t rank(TreeNode t) const;
  Rope root_of(TreeNode t) const;
  /// The first j points and the rest; r is used up.
  std::pair<Rope, Rope> split(Rope r, std::size_t j);
  /// a then b; both are used up.
  Rope join(Rope a, Rope b);
  /// The same ring from position j (j <= size(r)); r is used up.
  Rope rotate(Rope r, std::size_t j);
  void set_metres(TreeNode t, double m);
  /// The first point of least (y, then x): where ring_orientation (exact/ring.h) looks.
  TreeNode lowest(Rope r) const { return r == kNone ? kNone : nodes_[r].low; }
  /// Sum of the metres of positions [0, j), added in tree order (not left to right: the
  /// result differs from a running sum by rounding, within (j + depth) ulps of the total).
  double prefix_metres(Rope r, std::size_t j) const;
  double total_metres(Rope r) const { return r == kNone ? 0.0 : nodes_[r].sum; }
  /// A ring's sums (its closing segment, last point to first, included), added in tree
  /// order: within about 4 n rounding units of sum|term| of the same sums taken round the
  /// ring (coast/mean_width.cpp bounds the difference). The segment terms are
  /// sqrt(norm2(q - p)) and cross(p, q) for each point p and the next q.
  struct RingSums {
    std::size_t points = 0;
    double uv_perimeter = 0;
    double twice_area = 0;   // the shoelace sum: positive when anticlockwise
    Vec2 some_point{0, 0};   // one of its points (the tree's root)
  };
  RingSums ring_sums(Rope r) const;
  /// The largest norm2 of every point made so far (a bound for every rope's points).
  double max_norm2() const { return max_norm2_; }
  /// The tree node at the next position of t's rope (kNone after its last): one step up or
  /// down the tree from t, where at(rope, rank + 1) descends from the root again.
  TreeNode next(TreeNode t) const { return successor(t); }
  /// The tree nodes at the consecutive ring positions j, j+1, ... (mod size(r), r not
  /// empty) into out: one descent to j, then a step each (next, back to the first point
  /// after the last), where at() per position descends from the root every time.
  void run(Rope r, std::size_t j, std::span<TreeNode> out) const;
  /// Calls f(tree node) for every point in order.
  template <class F>
  void for_each(Rope r, F&& f) const {
    if (r == kNone) return;
    TreeNode t = leftmost(r);
    for (std::size_t i = 0, n = nodes_[r].size; i < n; ++i, t = successor(t)) f(t);
  }
  /// Its tree nodes go back to be reused; r is used up.
  void release(Rope r);
  /// Tree nodes visited by the operations so far (not by for_each): what tests bound.
  std::size_t work() const { return work_; }
  /// Tree nodes in use and held (for memory accounts).
  std::size_t capacity() const { return nodes_.size(); }

 private:
  struct Node {
    TreeNode left = kNone, right = kNone, parent = kNone;
    std::uint32_t size = 1;
    std::uint32_t id = 0;
    TreeNode low = kNone;
    Vec2 uv{0, 0};
    double metres = 0, sum = 0;
    // Over the segments inside the subtree (from each of its points but the last to the
    // next): the (u,v) lengths and the shoelace terms.
    double uv_length = 0, twice_area = 0;
  };
  TreeNode new_node(const Item& item);
  static std::uint32_t priority(TreeNode t);
  bool above(TreeNode a, TreeNode b) const;
  void pull(TreeNode t);
  void pull_path();
  TreeNode leftmost(TreeNode t) const;
  TreeNode rightmost(TreeNode t) const;
  TreeNode successor(TreeNode t) const;
  std::vector<Node> nodes_;
  std::vector<TreeNode> free_;
  std::vector<TreeNode> path_;   // scratch: nodes whose subtree changed, top-down
  mutable std::size_t work_ = 0;
  double max_norm2_ = 0;
};

}  // namespace sm::coast
