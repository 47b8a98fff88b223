// Triangle pairs into quadrangles: candidate pairs across interior edges, Gmsh's greedy
// order by corner angles, then (Matching) Edmonds' augmenting paths over the dual graph.
#include "mesh/recombine.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/id.h"
#include "exact/predicates.h"
#include "exact/quality.h"

namespace sm {
namespace {

// One candidate: triangles t1 < t2 across the edge (n1, n2); the quadrangle n1 n3 n2 n4
// (n3 apex of t1, n4 of t2) in t1's orientation.
struct Pair {
  std::uint32_t t1 = 0, t2 = 0;
  std::array<std::uint32_t, 4> quad{};
  double deviation = 0;   // max |90 - angle|, degrees
};

// The candidate pairs across interior, manifold, unfixed edges whose quadrangle is
// convex and good enough, best first (ties by triangle index).
std::vector<Pair> candidate_pairs(std::span<const std::array<std::uint32_t, 3>> tris, std::span<const Vec3> xyz,
                                  std::span<const Vec2> plane,
                                  std::span<const std::pair<std::uint32_t, std::uint32_t>> fixed,
                                  const RecombineOptions& opt) {
  const std::uint32_t nt = static_cast<std::uint32_t>(tris.size());
  // Interior edges: (smaller node, larger node, triangle, local edge) sorted, so the two
  // sides of an edge are neighbours.
  struct HalfEdge {
    std::uint32_t a, b, t, e;
  };
  std::vector<HalfEdge> he;
  he.reserve(3 * tris.size());
  for (std::uint32_t t = 0; t < nt; ++t)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t u = tris[t][e], v = tris[t][(e + 1) % 3];
      he.push_back({std::min(u, v), std::max(u, v), t, e});
    }
  std::sort(he.begin(), he.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.t < y.t);
  });
  std::vector<Pair> pairs;
  for (std::size_t k = 0; k + 1 < he.size(); ++k) {
    const HalfEdge &x = he[k], &y = he[k + 1];
    if (x.a != y.a || x.b != y.b) continue;
    if (k + 2 < he.size() && he[k + 2].a == x.a && he[k + 2].b == x.b) continue;   // not manifold: leave it
    if (std::binary_search(fixed.begin(), fixed.end(), std::make_pair(x.a, x.b))) continue;
    const auto& t1 = tris[x.t];
    const auto& t2 = tris[y.t];
    // In t1's orientation the edge runs n1 -> n2 and its apex n3 follows; t2's apex n4.
    const std::uint32_t n1 = t1[x.e], n2 = t1[(x.e + 1) % 3], n3 = t1[(x.e + 2) % 3], n4 = t2[(y.e + 2) % 3];
    // Convex when the other diagonal n3-n4 separates n1 from n2.
    const Sign s1 = orient2d(plane[n3], plane[n4], plane[n1]);
    const Sign s2 = orient2d(plane[n3], plane[n4], plane[n2]);
    if (s1 == Sign::Zero || s2 == Sign::Zero || s1 == s2) continue;
    // t1 = (n1, n2, n3) counter-clockwise, so the quadrangle goes n1, n4, n2, n3.
    Pair p{x.t, y.t, {n1, n4, n2, n3}, 0};
    p.deviation = 90.0 * (1.0 - quad_quality(xyz[n1], xyz[n4], xyz[n2], xyz[n3]));
    if (1.0 - p.deviation / 90.0 < opt.min_quality) continue;
    if (p.t1 > p.t2) std::swap(p.t1, p.t2);
    pairs.push_back(p);
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    return x.deviation != y.deviation ? x.deviation < y.deviation : (x.t1 != y.t1 ? x.t1 < y.t1 : x.t2 < y.t2);
  });
  return pairs;
}

// Edmonds' blossom search over the dual graph of the candidate pairs (maximum
// cardinality): from each unpaired triangle a breadth-first alternating tree, odd cycles
// shrunk to their base, an unpaired triangle reached ends an augmenting path, which is
// flipped. The per-vertex state is stamped per search, so a search costs what it visits,
// at most max_search triangles; every walk up the tree is bounded by the triangles the
// search touched.
class AugmentingPaths {
 public:
  AugmentingPaths(const std::vector<Pair>& pairs, std::uint32_t nt, std::vector<std::uint32_t>& mate,
                  std::uint32_t max_search)
      : pairs_(pairs), mate_(mate), max_search_(max_search), start_(nt + 1, 0), adj_(2 * pairs.size()),
        stamp_(nt, 0), parent_(nt), base_(nt), mark_(nt, 0), in_blossom_(nt, 0), used_(nt) {
    // The dual graph in CSR form (pair indices per triangle).
    for (const Pair& p : pairs) ++start_[p.t1 + 1], ++start_[p.t2 + 1];
    for (std::uint32_t t = 0; t < nt; ++t) start_[t + 1] += start_[t];
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < pairs.size(); ++i) adj_[fill[pairs[i].t1]++] = i, adj_[fill[pairs[i].t2]++] = i;
  }

  // Augments from every unpaired triangle with a candidate pair; the count of paths flipped.
  std::uint64_t run() {
    std::uint64_t flipped = 0;
    const auto nt = static_cast<std::uint32_t>(stamp_.size());
    for (std::uint32_t root = 0; root < nt; ++root) {
      if (mate_[root] != kNoIndex || start_[root] == start_[root + 1]) continue;
      const std::uint32_t end = search(root);
      if (end == kNoIndex) continue;
      // The path alternates unmatched and matched edges back to the root: at most the
      // triangles this search touched.
      std::uint32_t v = end;
      for (std::size_t step = 0; v != kNoIndex && step <= touched_.size(); ++step) {
        const std::uint32_t pv = parent_[v], next = mate_[pv];
        mate_[v] = pv, mate_[pv] = v;
        v = next;
      }
      ++flipped;
    }
    return flipped;
  }

  // The candidate pair joining t to its mate (kNoIndex when unpaired).
  std::uint32_t pair_of(std::uint32_t t) const {
    if (mate_[t] == kNoIndex) return kNoIndex;
    std::uint32_t found = kNoIndex;
    for (std::uint32_t k = start_[t]; k < start_[t + 1]; ++k)
      if (other(adj_[k], t) == mate_[t]) found = adj_[k];
    return found;
  }

 private:
  std::uint32_t other(std::uint32_t pi, std::uint32_t v) const {
    return pairs_[pi].t1 == v ? pairs_[pi].t2 : pairs_[pi].t1;
  }

  void touch(std::uint32_t v) {
    if (stamp_[v] == cur_) return;
    stamp_[v] = cur_, parent_[v] = kNoIndex, base_[v] = v, used_[v] = 0;
    touched_.push_back(v);
  }

  // The base of the innermost blossom holding both a and b: each walk goes up the
  // alternating tree, at most the triangles touched.
  std::uint32_t lca(std::uint32_t a, std::uint32_t b) {
    ++mark_stamp_;
    for (std::size_t step = 0; step <= touched_.size(); ++step) {
      a = base_[a];
      mark_[a] = mark_stamp_;
      if (mate_[a] == kNoIndex) break;
      a = parent_[mate_[a]];
    }
    for (std::size_t step = 0; step <= touched_.size(); ++step) {
      b = base_[b];
      if (mark_[b] == mark_stamp_) return b;
      b = parent_[mate_[b]];
    }
    return b;
  }

  void mark_path(std::uint32_t v, std::uint32_t b, std::uint32_t child) {
    for (std::size_t step = 0; base_[v] != b && step <= touched_.size(); ++step) {
      in_blossom_[base_[v]] = in_blossom_[base_[mate_[v]]] = blossom_stamp_;
      parent_[v] = child;
      child = mate_[v];
      v = parent_[mate_[v]];
    }
  }

  // An unpaired triangle reached by an augmenting path from root, or kNoIndex.
  std::uint32_t search(std::uint32_t root) {
    ++cur_;
    touched_.clear();
    touch(root);
    used_[root] = 1;
    queue_.assign(1, root);
    for (std::size_t q = 0; q < queue_.size(); ++q) {
      if (touched_.size() > max_search_) return kNoIndex;
      const std::uint32_t v = queue_[q];
      for (std::uint32_t k = start_[v]; k < start_[v + 1]; ++k) {
        const std::uint32_t to = other(adj_[k], v);
        touch(to);
        if (mate_[to] != kNoIndex) touch(mate_[to]);
        if (base_[v] == base_[to] || mate_[v] == to) continue;
        if (to == root || (mate_[to] != kNoIndex && parent_[mate_[to]] != kNoIndex)) {
          const std::uint32_t b = lca(v, to);
          ++blossom_stamp_;
          mark_path(v, b, to);
          mark_path(to, b, v);
          for (std::uint32_t i : touched_)
            if (in_blossom_[base_[i]] == blossom_stamp_) {
              base_[i] = b;
              if (!used_[i]) used_[i] = 1, queue_.push_back(i);
            }
        } else if (parent_[to] == kNoIndex) {
          parent_[to] = v;
          if (mate_[to] == kNoIndex) return to;
          used_[mate_[to]] = 1;
          queue_.push_back(mate_[to]);
        }
      }
    }
    return kNoIndex;
  }

  const std::vector<Pair>& pairs_;
  std::vector<std::uint32_t>& mate_;   // triangle -> its partner
  std::uint32_t max_search_;
  std::vector<std::uint32_t> start_, adj_;
  std::vector<std::uint32_t> stamp_, parent_, base_, mark_, in_blossom_;
  std::vector<std::uint8_t> used_;
  std::vector<std::uint32_t> touched_, queue_;
  std::uint32_t cur_ = 0, mark_stamp_ = 0, blossom_stamp_ = 0;
};

}  // namespace

RecombineResult recombine(std::span<const std::array<std::uint32_t, 3>> tris, std::span<const Vec3> xyz,
                          std::span<const Vec2> plane, std::span<const std::pair<std::uint32_t, std::uint32_t>> fixed,
                          const RecombineOptions& opt) {
  RecombineResult res;
  const std::uint32_t nt = static_cast<std::uint32_t>(tris.size());
  const std::vector<Pair> pairs = candidate_pairs(tris, xyz, plane, fixed, opt);
  // Gmsh's greedy pass: the best pairs first.
  std::vector<std::uint32_t> mate(nt, kNoIndex);        // triangle -> its partner
  std::vector<std::uint32_t> mate_pair(nt, kNoIndex);   // triangle -> its pair's index
  for (std::uint32_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    if (mate[p.t1] != kNoIndex || mate[p.t2] != kNoIndex) continue;
    mate[p.t1] = p.t2, mate[p.t2] = p.t1;
    mate_pair[p.t1] = mate_pair[p.t2] = i;
  }
  if (opt.algorithm == RecombineAlgorithm::Matching) {
    AugmentingPaths paths(pairs, nt, mate, opt.max_search);
    res.augmentations = paths.run();
    for (std::uint32_t t = 0; t < nt; ++t) mate_pair[t] = paths.pair_of(t);
  }
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (mate[t] == kNoIndex) {
      res.triangles.push_back(tris[t]);
    } else if (t < mate[t]) {
      res.quads.push_back(pairs[mate_pair[t]].quad);
    }
  }
  return res;
}

}  // namespace sm
