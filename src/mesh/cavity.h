// The Bowyer-Watson cavity of mesh/: the search for the triangles whose circumcircle
// holds the new point, and the pairing of the fan that refills it. One algorithm for the
// Delaunay construction (mesh/delaunay.cpp: its own triangle array with ghosts) and the
// constrained insertion (mesh/insert.cpp: the TriangleStore, stopped by constraints);
// each says through a `Host` how its triangles are stored.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/id.h"

namespace sm {

/// Depth-first search of the cavity from triangle t0 (in conflict with the point): the
/// host provides
///   void start(std::uint32_t t0)                     t0 is visited
///   bool neighbour(std::uint32_t t, std::uint32_t e, std::uint32_t& nt)
///                                                    the triangle across side e of t, if
///                                                    the cavity may reach it
///   bool visited(std::uint32_t nt)
///   bool in_conflict(std::uint32_t nt)               circumcircle holds the point
///   void visit(std::uint32_t nt)                     nt joins the search (after the push)
///   void boundary(std::uint32_t t, std::uint32_t e)  side e of t bounds the cavity
/// `cavity` gets the triangles in the order they are taken from the stack; each triangle
/// is pushed once, so the search ends within the triangle count.
template <class Host>
inline void cavity_search(Host& h, std::uint32_t t0, std::vector<std::uint32_t>& stack,
                          std::vector<std::uint32_t>& cavity) {
  cavity.clear();
  stack.assign(1, t0);
  h.start(t0);
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    cavity.push_back(t);
    for (std::uint32_t e = 0; e < 3; ++e) {
      std::uint32_t nt = 0;
      if (h.neighbour(t, e, nt)) {
        if (h.visited(nt)) continue;
        if (h.in_conflict(nt)) {
          stack.push_back(nt);
          h.visit(nt);
          continue;
        }
      }
      h.boundary(t, e);
    }
  }
}

/// The refill pairs the side b -> p of the new triangle on boundary edge i (a_i -> b_i)
/// with the side p -> b of the one on the edge j that starts at b_i: pair(i, j) for each
/// i in turn. False, at the first edge whose successor is missing, when the boundary does
/// not close (a corrupt triangulation): a caller that must not change anything then
/// records the pairs and makes them only after the whole boundary has passed. key(v) is
/// a vertex's index in `vmap` (below `keys`), used once the boundary is long; short ones
/// (nearly all) search the list, which stays in cache. The pairs are made as they are
/// found: a separate list of successors cost the Delaunay construction 6% of its time.
template <class Bound, class Key, class Pair>
inline bool fan_pairs(const std::vector<Bound>& bound, Key key, std::size_t keys, std::vector<std::uint32_t>& vmap,
                      Pair pair) {
  const std::size_t k = bound.size();
  if (k <= 16) {
    for (std::size_t i = 0; i < k; ++i) {
      std::size_t j = 0;
      while (j < k && bound[j].a != bound[i].b) ++j;
      if (j == k) return false;
      pair(i, j);
    }
    return true;
  }
  // The map is never cleared: an entry is trusted only when it names an edge of this
  // boundary that starts at the vertex.
  if (vmap.size() < keys) vmap.resize(keys + keys / 2, kNoIndex);
  for (std::size_t i = 0; i < k; ++i) vmap[key(bound[i].a)] = static_cast<std::uint32_t>(i);
  for (std::size_t i = 0; i < k; ++i) {
    const std::uint32_t j = vmap[key(bound[i].b)];
    if (!(j < k && bound[j].a == bound[i].b)) return false;
    pair(i, std::size_t{j});
  }
  return true;
}

}  // namespace sm
