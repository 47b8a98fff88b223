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

}  // namespace

RecombineResult recombine(std::span<const std::array<std::uint32_t, 3>> tris, std::span<const Vec3> xyz,
                          std::span<const Vec2> plane, std::span<const std::pair<std::uint32_t, std::uint32_t>> fixed,
                          const RecombineOptions& opt) {
  RecombineResult res;
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
  std::vector<std::uint32_t> mate(nt, kNoIndex);     // triangle -> its partner
  std::vector<std::uint32_t> mate_pair(nt, kNoIndex);   // triangle -> its pair's index
  for (std::uint32_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    if (mate[p.t1] != kNoIndex || mate[p.t2] != kNoIndex) continue;
    mate[p.t1] = p.t2, mate[p.t2] = p.t1;
    mate_pair[p.t1] = mate_pair[p.t2] = i;
  }
  if (opt.algorithm == RecombineAlgorithm::Matching) {
    // The dual graph of the candidate pairs, in CSR form (pair indices per triangle).
    std::vector<std::uint32_t> start(nt + 1, 0), adj(2 * pairs.size());
    for (const Pair& p : pairs) ++start[p.t1 + 1], ++start[p.t2 + 1];
    for (std::uint32_t t = 0; t < nt; ++t) start[t + 1] += start[t];
    {
      std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
      for (std::uint32_t i = 0; i < pairs.size(); ++i) adj[fill[pairs[i].t1]++] = i, adj[fill[pairs[i].t2]++] = i;
    }
    // Edmonds' blossom search from each unpaired triangle (maximum cardinality): a
    // breadth-first alternating tree, odd cycles shrunk to their base, an unpaired
    // triangle reached ends an augmenting path, which is flipped. The per-vertex state
    // is stamped per search, so a search costs what it visits, at most max_search.
    std::vector<std::uint32_t> stamp(nt, 0), parent(nt), base(nt), mark(nt, 0), in_blossom(nt, 0);
    std::vector<std::uint8_t> used(nt);
    std::vector<std::uint32_t> touched, queue;
    std::uint32_t cur = 0, mark_stamp = 0, blossom_stamp = 0;
    auto touch = [&](std::uint32_t v) {
      if (stamp[v] == cur) return;
      stamp[v] = cur, parent[v] = kNoIndex, base[v] = v, used[v] = 0;
      touched.push_back(v);
    };
    auto lca = [&](std::uint32_t a, std::uint32_t b) {
      ++mark_stamp;
      while (true) {
        a = base[a];
        mark[a] = mark_stamp;
        if (mate[a] == kNoIndex) break;
        a = parent[mate[a]];
      }
      while (true) {
        b = base[b];
        if (mark[b] == mark_stamp) return b;
        b = parent[mate[b]];
      }
    };
    auto mark_path = [&](std::uint32_t v, std::uint32_t b, std::uint32_t child) {
      while (base[v] != b) {
        in_blossom[base[v]] = in_blossom[base[mate[v]]] = blossom_stamp;
        parent[v] = child;
        child = mate[v];
        v = parent[mate[v]];
      }
    };
    auto other = [&](std::uint32_t pi, std::uint32_t v) { return pairs[pi].t1 == v ? pairs[pi].t2 : pairs[pi].t1; };
    auto search = [&](std::uint32_t root) -> std::uint32_t {
      ++cur;
      touched.clear();
      touch(root);
      used[root] = 1;
      queue.assign(1, root);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        if (touched.size() > opt.max_search) return kNoIndex;
        const std::uint32_t v = queue[q];
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
          const std::uint32_t to = other(adj[k], v);
          touch(to);
          if (mate[to] != kNoIndex) touch(mate[to]);
          if (base[v] == base[to] || mate[v] == to) continue;
          if (to == root || (mate[to] != kNoIndex && parent[mate[to]] != kNoIndex)) {
            const std::uint32_t b = lca(v, to);
            ++blossom_stamp;
            mark_path(v, b, to);
            mark_path(to, b, v);
            for (std::uint32_t i : touched)
              if (in_blossom[base[i]] == blossom_stamp) {
                base[i] = b;
                if (!used[i]) used[i] = 1, queue.push_back(i);
              }
          } else if (parent[to] == kNoIndex) {
            parent[to] = v;
            if (mate[to] == kNoIndex) return to;
            used[mate[to]] = 1;
            queue.push_back(mate[to]);
          }
        }
      }
      return kNoIndex;
    };
    for (std::uint32_t root = 0; root < nt; ++root) {
      if (mate[root] != kNoIndex || start[root] == start[root + 1]) continue;
      const std::uint32_t end = search(root);
      if (end == kNoIndex) continue;
      for (std::uint32_t v = end; v != kNoIndex;) {
        const std::uint32_t pv = parent[v], next = mate[pv];
        mate[v] = pv, mate[pv] = v;
        v = next;
      }
      ++res.augmentations;
    }
    // The pair of each matched triangle.
    for (std::uint32_t t = 0; t < nt; ++t) {
      mate_pair[t] = kNoIndex;
      if (mate[t] == kNoIndex) continue;
      for (std::uint32_t k = start[t]; k < start[t + 1]; ++k)
        if (other(adj[k], t) == mate[t]) mate_pair[t] = adj[k];
    }
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
