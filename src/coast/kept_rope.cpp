// Ropes of kept ring points as implicit treaps (kept_rope.h). Split and join go down one
// path and pull the aggregates back up it, without recursion (depth is O(log n) expected).
#include "coast/kept_rope.h"

#include <algorithm>
#include <cmath>

#include "base/check.h"

namespace sm::coast {

std::uint32_t KeptRopes::priority(TreeNode t) {
  // The murmur3 finaliser: tree nodes are numbered in ring order, so the priority must not
  // follow the number (a treap with ordered priorities is a list).
  std::uint32_t h = t;
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

bool KeptRopes::above(TreeNode a, TreeNode b) const {
  const std::uint32_t pa = priority(a), pb = priority(b);
  return pa > pb || (pa == pb && a < b);
}

KeptRopes::TreeNode KeptRopes::new_node(const Item& item) {
  TreeNode t;
  if (!free_.empty()) {
    t = free_.back();
    free_.pop_back();
  } else {
    SM_ASSERT(nodes_.size() < kNone, "KeptRopes: more points than 32-bit tree node ids (kept_rope.cpp, new_node)");
    t = static_cast<TreeNode>(nodes_.size());
    nodes_.emplace_back();
  }
  Node& n = nodes_[t];
  n = Node{};
  n.id = item.id;
  n.uv = item.uv;
  n.metres = item.metres;
  n.sum = item.metres;
  n.low = t;
  max_norm2_ = std::max(max_norm2_, norm2(item.uv));
  return t;
}

void KeptRopes::pull(TreeNode t) {
  Node& n = nodes_[t];
  n.size = 1;
  n.sum = n.metres;
  n.low = t;
  n.uv_length = n.twice_area = 0;
  // The segment from the last point of the part before to the first of the part after
  // (found down the subtree's spine: its length is O(log n) expected, and over all the
  // tree nodes of a rope each node is on two such spines at most, so make stays O(n)).
  auto link = [&](TreeNode a, TreeNode b) {
    const Vec2 p = nodes_[a].uv, q = nodes_[b].uv;
    n.uv_length = n.uv_length + std::sqrt(norm2(q - p));
    n.twice_area = n.twice_area + cross(p, q);
  };
  auto lower = [&](TreeNode a, TreeNode b) {   // b strictly before a in (y, x)
    const Vec2 p = nodes_[a].uv, q = nodes_[b].uv;
    return q.y < p.y || (q.y == p.y && q.x < p.x);
  };
  if (n.left != kNone) {
    const Node& l = nodes_[n.left];
    n.size += l.size;
    n.sum = l.sum + n.sum;
    if (!lower(l.low, t)) n.low = l.low;   // ties go to the earlier point
    n.uv_length = l.uv_length;
    n.twice_area = l.twice_area;
    TreeNode a = n.left;   // the left part's last point
    while (nodes_[a].right != kNone) a = nodes_[a].right, ++work_;
    link(a, t);
  }
  if (n.right != kNone) {
    const Node& r = nodes_[n.right];
    n.size += r.size;
    n.sum = n.sum + r.sum;
    if (lower(n.low, r.low)) n.low = r.low;
    TreeNode b = n.right;   // the right part's first point
    while (nodes_[b].left != kNone) b = nodes_[b].left, ++work_;
    link(t, b);
    n.uv_length = n.uv_length + r.uv_length;
    n.twice_area = n.twice_area + r.twice_area;
  }
}

void KeptRopes::pull_path() {
  for (std::size_t i = path_.size(); i-- > 0;) pull(path_[i]);
}

KeptRopes::Rope KeptRopes::make(std::span<const Item> items) {
  // The Cartesian tree of the priorities by a stack of the right spine (O(n)).
  path_.clear();
  for (const Item& item : items) {
    const TreeNode t = new_node(item);
    TreeNode last = kNone;
    while (!path_.empty() && above(t, path_.back())) last = path_.back(), path_.pop_back();
    nodes_[t].left = last;
    if (last != kNone) nodes_[last].parent = t;
    if (!path_.empty()) nodes_[path_.back()].right = t, nodes_[t].parent = path_.back();
    path_.push_back(t);
  }
  if (path_.empty()) return kNone;
  const Rope root = path_.front();
  nodes_[root].parent = kNone;
  // Aggregates bottom-up: breadth-first from the root, pulled in reverse.
  path_.assign(1, root);
  for (std::size_t i = 0; i < path_.size(); ++i) {
    const Node& n = nodes_[path_[i]];
    if (n.left != kNone) path_.push_back(n.left);
    if (n.right != kNone) path_.push_back(n.right);
  }
  pull_path();
  return root;
}

KeptRopes::TreeNode KeptRopes::at(Rope r, std::size_t j) const {
  SM_ASSERT(j < size(r), "KeptRopes: a position past the rope's end (kept_rope.cpp, at)");
  TreeNode t = r;
  for (;;) {
    ++work_;
    const std::size_t ls = size(nodes_[t].left);
    if (j < ls) {
      t = nodes_[t].left;
    } else if (j == ls) {
      return t;
    } else {
      j -= ls + 1;
      t = nodes_[t].right;
    }
  }
}

std::size_t KeptRopes::rank(TreeNode t) const {
  std::size_t r = size(nodes_[t].left);
  for (TreeNode p = nodes_[t].parent; p != kNone; t = p, p = nodes_[p].parent) {
    ++work_;
    if (nodes_[p].right == t) r += size(nodes_[p].left) + 1;
  }
  return r;
}

KeptRopes::Rope KeptRopes::root_of(TreeNode t) const {
  while (nodes_[t].parent != kNone) t = nodes_[t].parent, ++work_;
  return t;
}

std::pair<KeptRopes::Rope, KeptRopes::Rope> KeptRopes::split(Rope r, std::size_t j) {
  if (j == 0) return {kNone, r};
  if (j >= size(r)) return {r, kNone};
  Rope first = kNone, rest = kNone;
  TreeNode* first_hook = &first;   // where first's next node hangs (its rightmost open slot)
  TreeNode* rest_hook = &rest;     // and rest's (its leftmost open slot)
  TreeNode first_parent = kNone, rest_parent = kNone;
  path_.clear();
  for (TreeNode t = r; t != kNone;) {
    ++work_;
    path_.push_back(t);
    Node& n = nodes_[t];
    const std::size_t ls = size(n.left);
    if (j <= ls) {
      *rest_hook = t;
      n.parent = rest_parent;
      rest_parent = t;
      rest_hook = &n.left;
      t = n.left;
    } else {
      *first_hook = t;
      n.parent = first_parent;
      first_parent = t;
      first_hook = &n.right;
      j -= ls + 1;
      t = n.right;
    }
  }
  *first_hook = kNone;
  *rest_hook = kNone;
  pull_path();
  return {first, rest};
}

KeptRopes::Rope KeptRopes::join(Rope a, Rope b) {
  if (a == kNone) return b;
  if (b == kNone) return a;
  Rope root = kNone;
  TreeNode* hook = &root;
  TreeNode parent = kNone;
  path_.clear();
  while (a != kNone && b != kNone) {
    ++work_;
    if (above(a, b)) {   // a's root on top, b joins its right subtree
      *hook = a;
      nodes_[a].parent = parent;
      parent = a;
      path_.push_back(a);
      hook = &nodes_[a].right;
      a = nodes_[a].right;
    } else {
      *hook = b;
      nodes_[b].parent = parent;
      parent = b;
      path_.push_back(b);
      hook = &nodes_[b].left;
      b = nodes_[b].left;
    }
  }
  const TreeNode rest = a != kNone ? a : b;
  *hook = rest;
  if (rest != kNone) nodes_[rest].parent = parent;
  pull_path();
  return root;
}

KeptRopes::Rope KeptRopes::rotate(Rope r, std::size_t j) {
  if (j == 0 || j >= size(r)) return r;
  const auto [first, rest] = split(r, j);
  return join(rest, first);
}

void KeptRopes::set_metres(TreeNode t, double m) {
  // Only the metres' sums change (the same sums as pull's, in the same order); the points,
  // their order and so the other aggregates stay.
  nodes_[t].metres = m;
  for (; t != kNone; t = nodes_[t].parent) {
    ++work_;
    Node& n = nodes_[t];
    n.sum = n.metres;
    if (n.left != kNone) n.sum = nodes_[n.left].sum + n.sum;
    if (n.right != kNone) n.sum = n.sum + nodes_[n.right].sum;
  }
}

double KeptRopes::prefix_metres(Rope r, std::size_t j) const {
  double s = 0;
  for (TreeNode t = r; t != kNone && j > 0;) {
    ++work_;
    const Node& n = nodes_[t];
    const std::size_t ls = size(n.left);
    if (j < ls) {
      t = n.left;
      continue;
    }
    if (n.left != kNone) s += nodes_[n.left].sum;
    if (j == ls) break;
    s += n.metres;
    j -= ls + 1;
    t = n.right;
  }
  return s;
}

KeptRopes::RingSums KeptRopes::ring_sums(Rope r) const {
  RingSums s;
  if (r == kNone) return s;
  const Node& n = nodes_[r];
  const Vec2 p = nodes_[rightmost(r)].uv, q = nodes_[leftmost(r)].uv;   // the closing segment
  s.points = n.size;
  s.uv_perimeter = n.uv_length + std::sqrt(norm2(q - p));
  s.twice_area = n.twice_area + cross(p, q);
  s.some_point = n.uv;
  return s;
}

void KeptRopes::release(Rope r) {
  if (r == kNone) return;
  const std::size_t before = free_.size();
  for_each(r, [&](TreeNode t) { free_.push_back(t); });
  // Marked only once all are listed: for_each walks by the parent links.
  for (std::size_t i = before; i < free_.size(); ++i) nodes_[free_[i]].parent = kNone;
}

void KeptRopes::run(Rope r, std::size_t j, std::span<TreeNode> out) const {
  if (out.empty()) return;
  TreeNode t = at(r, j % size(r));
  out[0] = t;
  for (std::size_t i = 1; i < out.size(); ++i) {
    t = successor(t);
    if (t == kNone) t = leftmost(r);
    out[i] = t;
  }
}

KeptRopes::TreeNode KeptRopes::leftmost(TreeNode t) const {
  while (nodes_[t].left != kNone) t = nodes_[t].left;
  return t;
}

KeptRopes::TreeNode KeptRopes::rightmost(TreeNode t) const {
  while (nodes_[t].right != kNone) t = nodes_[t].right;
  return t;
}

KeptRopes::TreeNode KeptRopes::successor(TreeNode t) const {
  if (nodes_[t].right != kNone) return leftmost(nodes_[t].right);
  TreeNode p = nodes_[t].parent;
  while (p != kNone && nodes_[p].right == t) t = p, p = nodes_[p].parent;
  return p;
}

}  // namespace sm::coast
