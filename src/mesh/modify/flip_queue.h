// The edges a cascade of flips still has to test (the Lawson flips of smooth.cpp, the
// quality swaps of swap.cpp): a stack of sides, each edge on it at most once.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangulation.h"

namespace sm {

struct FlipQueue {
  std::vector<Side> stack;
  std::vector<std::uint8_t> queued;   // per side: 1 while its edge is on the stack

  explicit FlipQueue(std::size_t sides) : queued(sides, 0) {}

  /// Queues the edge of s, keyed by the smaller of its two sides, unless it is on the hull,
  /// constrained or already queued.
  void push_edge(const TriangleStore& m, Side s) {
    push_edge(m, s, [](Side) { return false; });
  }
  /// The same, also passing over an edge whose key `queued_elsewhere(key)` says is waiting
  /// below the stack without being stored on it (smooth.cpp's pre-tested make_delaunay).
  template <class QueuedElsewhere>
  void push_edge(const TriangleStore& m, Side s, QueuedElsewhere&& queued_elsewhere) {
    const Side o = m.twin[s.value];
    if (!o.valid() || m.constrained(s)) return;
    const Side key = s.value < o.value ? s : o;
    if (!queued[key.value] && !queued_elsewhere(key)) queued[key.value] = 1, stack.push_back(key);
  }

  /// After m.flip returned n (the new edge d -> c): the four outer edges of the quad, which
  /// the flip may have made flippable.
  void push_outer_edges(const TriangleStore& m, Side n) {
    push_outer_edges(m, n, [](Side) { return false; });
  }
  template <class QueuedElsewhere>
  void push_outer_edges(const TriangleStore& m, Side n, QueuedElsewhere&& queued_elsewhere) {
    const Side o = m.twin[n.value];
    for (Side x : {next(n), prev(n), next(o), prev(o)}) push_edge(m, x, queued_elsewhere);
  }

  bool empty() const { return stack.empty(); }

  Side pop() {
    const Side s = stack.back();
    stack.pop_back();
    queued[s.value] = 0;
    return s;
  }
};

}  // namespace sm
