// sorted_side_keys (side_keys.h): a counting sort on the smaller node, then each node's
// few keys sorted in place; a comparison sort where the surface's node numbers are
// spread far wider than its sides (a small surface of a large mesh).
#include "mesh/side_keys.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <utility>
#include <vector>

#include "base/check.h"
#include "base/parallel.h"

namespace sm {
namespace {

// Elements (or nodes) per chunk of each pass: fixed, so that the work is cut alike for every
// thread count (the result does not depend on the cut: each node's keys are sorted last).
constexpr std::size_t kSideChunk = 1 << 15;
// Below this many sides the comparison sort costs nothing worth a pass over a node range.
constexpr std::size_t kCountingMinSides = 4096;

// fn(a, b) for each side of the elements [begin, end) of sf, triangles first.
template <class Fn>
void for_each_side(const SurfaceMesh& sf, std::size_t begin, std::size_t end, const Fn& fn) {
  const std::size_t nt = sf.triangles.size();
  for (std::size_t i = begin; i < std::min(end, nt); ++i) {
    const auto& t = sf.triangles[i];
    fn(t[0], t[1]), fn(t[1], t[2]), fn(t[2], t[0]);
  }
  for (std::size_t i = std::max(begin, nt); i < end; ++i) {
    const auto& q = sf.quads[i - nt];
    fn(q[0], q[1]), fn(q[1], q[2]), fn(q[2], q[3]), fn(q[3], q[0]);
  }
}

// c++, as one step when other threads bump the same counters (Shared).
template <bool Shared>
std::uint32_t bump(std::uint32_t& c) {
  if constexpr (Shared)
    return std::atomic_ref<std::uint32_t>(c).fetch_add(1, std::memory_order_relaxed);
  else
    return c++;
}

// The smallest and largest node of sf's elements.
std::pair<std::uint32_t, std::uint32_t> node_range(const SurfaceMesh& sf, int threads) {
  const std::size_t n = sf.triangles.size() + sf.quads.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> chunk_range((n + kSideChunk - 1) / kSideChunk,
                                                                   {std::numeric_limits<std::uint32_t>::max(), 0});
  parallel_for_chunks(threads, n, kSideChunk, [&](std::size_t begin, std::size_t end) {
    // A plain reference, not a structured binding: clang before 16 cannot capture bindings.
    auto& range = chunk_range[begin / kSideChunk];
    for_each_side(sf, begin, end, [&](std::uint32_t a, std::uint32_t) {
      range.first = std::min(range.first, a), range.second = std::max(range.second, a);
    });
  });
  std::pair<std::uint32_t, std::uint32_t> r{std::numeric_limits<std::uint32_t>::max(), 0};
  for (const auto& [lo, hi] : chunk_range) r = {std::min(r.first, lo), std::max(r.second, hi)};
  return r;
}

// The counting sort: cursor (one counter per node of [lo, lo + cursor.size() - 1), zeroed)
// counts each node's keys, becomes where they begin, then (as they are placed) where they end.
template <bool Shared>
void counting_sort(const SurfaceMesh& sf, std::uint32_t lo, std::span<std::uint32_t> cursor, std::span<EdgeKey> out,
                   int threads) {
  const std::size_t n = sf.triangles.size() + sf.quads.size();
  parallel_for_chunks(threads, n, kSideChunk, [&](std::size_t begin, std::size_t end) {
    for_each_side(sf, begin, end,
                  [&](std::uint32_t a, std::uint32_t b) { bump<Shared>(cursor[std::min(a, b) - lo + 1]); });
  });
  for (std::size_t k = 1; k < cursor.size(); ++k) cursor[k] += cursor[k - 1];
  parallel_for_chunks(threads, n, kSideChunk, [&](std::size_t begin, std::size_t end) {
    for_each_side(sf, begin, end, [&](std::uint32_t a, std::uint32_t b) {
      out[bump<Shared>(cursor[std::min(a, b) - lo])] = undirected_key(a, b);
    });
  });
  // Node k's keys, [cursor[k - 1], cursor[k]) now, in the order the threads placed them:
  // sorted, they are the same for any count. A node has a few (its degree at most).
  parallel_for_chunks(threads, cursor.size() - 1, kSideChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      EdgeKey* first = out.data() + (k == 0 ? 0 : cursor[k - 1]);
      EdgeKey* last = out.data() + cursor[k];
      for (EdgeKey* i = first + (first != last); i < last; ++i) {
        const EdgeKey key = *i;
        EdgeKey* j = i;
        for (; j > first && *(j - 1) > key; --j) *j = *(j - 1);
        *j = key;
      }
    }
  });
}

}  // namespace

std::size_t side_count(const SurfaceMesh& sf) { return 3 * sf.triangles.size() + 4 * sf.quads.size(); }

void sorted_side_keys(const SurfaceMesh& sf, std::span<EdgeKey> out, int threads) {
  const std::size_t sides = side_count(sf);
  SM_ASSERT(out.size() == sides, "sorted_side_keys: the output holds one key per side");
  if (sides == 0) return;
  threads = std::max(threads, 1);
  const auto [lo, hi] = node_range(sf, threads);
  const std::size_t nodes = std::size_t{hi} - lo + 1;
  // The counters are 32-bit, and a node range far wider than the sides is mostly empty.
  if (sides < kCountingMinSides || nodes > 2 * sides || sides > std::numeric_limits<std::uint32_t>::max()) {
    std::size_t w = 0;
    for_each_side(sf, 0, sf.triangles.size() + sf.quads.size(),
                  [&](std::uint32_t a, std::uint32_t b) { out[w++] = undirected_key(a, b); });
    std::sort(out.begin(), out.end());
    return;
  }
  std::vector<std::uint32_t> cursor(nodes + 1, 0);
  if (threads > 1)
    counting_sort<true>(sf, lo, cursor, out, threads);
  else
    counting_sort<false>(sf, lo, cursor, out, 1);
}

}  // namespace sm
