// The exact nearest-point k-d tree: its construction and its two searches (from the root,
// and from the query's leaf upwards), which give the same answer.
#include "field/near_tree.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <utility>

#include "base/parallel.h"

namespace sm::field {

NearTree::NearTree(std::span<const Vec3> pts, int threads) {
  const std::size_t n = pts.size();
  if (n == 0) return;
  std::vector<std::uint32_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::uint32_t>(i);
  nodes_.resize(1 + std::size_t{descendants(static_cast<std::uint32_t>(n), 0)});
  // The top levels here, the subtrees below them on the threads: each reorders its own
  // range of ids and writes its own nodes, numbered as one depth-first build numbers them.
  std::vector<Subtree> deferred;
  std::uint32_t next = 1;
  build(pts, ids, 0, 0, static_cast<std::uint32_t>(n), 0, next, &deferred);
  parallel_for_chunks(threads, deferred.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      const Subtree& s = deferred[t];
      std::uint32_t below = s.next;
      build(pts, ids, s.k, s.begin, s.end, s.depth, below, nullptr);
    }
  });
  x_.resize(n), y_.resize(n), z_.resize(n), id_ = ids;
  constexpr std::size_t kChunk = std::size_t{1} << 15;
  parallel_for_chunks(threads, n, kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) x_[k] = pts[ids[k]].x, y_[k] = pts[ids[k]].y, z_[k] = pts[ids[k]].z;
  });
}

std::uint32_t NearTree::descendants(std::uint32_t count, std::size_t depth) {
  // A level's nodes have at most two sizes (halves differ by at most one point): one
  // answer kept per size and level, so about two nodes a level are visited, not every one.
  std::map<std::pair<std::uint32_t, std::size_t>, std::uint32_t> known;
  const auto below = [&known](const auto& self, std::uint32_t c, std::size_t d) -> std::uint32_t {
    if (!(c > kLeaf && d + 1 < kMaxDepth)) return 0;
    if (const auto it = known.find({c, d}); it != known.end()) return it->second;
    const std::uint32_t lo = c / 2;
    const std::uint32_t v = 2 + self(self, lo, d + 1) + self(self, c - lo, d + 1);
    known.emplace(std::make_pair(c, d), v);
    return v;
  };
  return below(below, count, depth);
}

void NearTree::build(std::span<const Vec3> pts, std::vector<std::uint32_t>& ids, std::uint32_t k,
                     std::uint32_t begin, std::uint32_t end, std::size_t depth, std::uint32_t& next,
                     std::vector<Subtree>* deferred) {
  if (deferred && depth == kSubtreeDepth) {
    deferred->push_back({k, begin, end, depth, next});
    next += descendants(end - begin, depth);
    return;
  }
  Node nd;
  nd.begin = begin, nd.end = end;
  for (int a = 0; a < 3; ++a) nd.lo[a] = std::numeric_limits<double>::infinity(), nd.hi[a] = -nd.lo[a];
  for (std::uint32_t m = begin; m < end; ++m) {
    const Vec3& p = pts[ids[m]];
    const double c[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) nd.lo[a] = std::min(nd.lo[a], c[a]), nd.hi[a] = std::max(nd.hi[a], c[a]);
  }
  if (end - begin > kLeaf && depth + 1 < kMaxDepth) {
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (nd.hi[a] - nd.lo[a] > nd.hi[axis] - nd.lo[axis]) axis = a;
    // Point i's coordinate on the axis: the axis-th double of pts[i] (Vec3 is three doubles).
    const double* coord = &pts[0].x + axis;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end,
                     [coord](std::uint32_t i, std::uint32_t j) { return coord[3 * i] < coord[3 * j]; });
    nd.child = next;
    nd.axis = static_cast<std::uint32_t>(axis);
    next += 2;
    nodes_[k] = nd;
    build(pts, ids, nd.child, begin, mid, depth + 1, next, deferred);
    build(pts, ids, nd.child + 1, mid, end, depth + 1, next, deferred);
    return;
  }
  nodes_[k] = nd;
}

void NearTree::search(const Vec3& q, double& best2, std::uint32_t& best) const {
  if (nodes_.empty()) return;
  walk(q, 0, box2(nodes_[0], q), best2, [&](std::uint32_t m, double d2) {
    if (d2 < best2 || (d2 == best2 && id_[m] < best)) best2 = d2, best = id_[m];
  });
}

// Down: at each inner node q takes the child whose side of the split it is on, and the
// other child's gap along the split's axis bounds (below) every computed squared distance
// from q to a point of that child: for a point beyond the gap the coordinate difference,
// rounded, is at least the rounded gap (rounding is monotone), and the sum of the three
// squares at least its square. reach[l] is the least such bound over the levels above l:
// every point outside the level-l node's subtree is at least that far.
//
// Up: once the level-l subtree is searched, a point outside it can only win when
// reach[l] <= best2; else the search is over.
void NearTree::search_up(const Vec3& q, double& best2, std::uint32_t& best) const {
  if (nodes_.empty()) return;
  std::uint32_t other[kMaxDepth];  // not initialised: written on the way down
  double reach[kMaxDepth + 1];
  const double c[3] = {q.x, q.y, q.z};
  std::size_t l = 0;
  std::uint32_t k = 0;
  reach[0] = std::numeric_limits<double>::infinity();
  while (nodes_[k].child != 0) {
    const Node& nd = nodes_[k];
    const Node& second = nodes_[nd.child + 1];
    const double at = c[nd.axis];
    double gap = 0;
    if (at < second.lo[nd.axis]) {
      gap = second.lo[nd.axis] - at;
      other[l] = nd.child + 1;
      k = nd.child;
    } else {
      const double first_hi = nodes_[nd.child].hi[nd.axis];
      gap = at > first_hi ? at - first_hi : 0.0;  // 0 also for a NaN
      other[l] = nd.child;
      k = nd.child + 1;
    }
    reach[l + 1] = std::min(reach[l], gap * gap);
    ++l;
  }
  const auto leaf = [&](std::uint32_t m, double d2) {
    if (d2 < best2 || (d2 == best2 && id_[m] < best)) best2 = d2, best = id_[m];
  };
  const Node& nd = nodes_[k];
  for (std::uint32_t m = nd.begin; m < nd.end; ++m) {
    const double dx = x_[m] - q.x, dy = y_[m] - q.y, dz = z_[m] - q.z;
    leaf(m, dx * dx + dy * dy + dz * dz);
  }
  while (l > 0 && !(reach[l] > best2)) {
    --l;
    walk(q, other[l], box2(nodes_[other[l]], q), best2, leaf);
  }
}

}  // namespace sm::field
