// A sort on threads whose result does not depend on the thread count: runs of fixed
// length sorted on their own, then merged pairwise (std::merge, stable) in rounds.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "base/parallel.h"

namespace sm {

/// Sorts v by `less` (a strict weak order) on up to `threads` threads. The result is the
/// same bytes for every thread count: runs of `run` elements are sorted with std::sort,
/// then merged, and the bounds of both depend only on v.size(). Equal elements end in an
/// order of their own (as with std::sort), the same for every count. Needs a default
/// constructible T (a second array of v's size is made for the merges).
template <class T, class Less>
void parallel_sort(int threads, std::vector<T>& v, Less less, std::size_t run = std::size_t{1} << 15) {
  const std::size_t n = v.size();
  if (n <= run) {
    std::sort(v.begin(), v.end(), less);
    return;
  }
  const auto at = [](std::vector<T>& a, std::size_t i) { return a.begin() + static_cast<std::ptrdiff_t>(i); };
  parallel_for_chunks(threads, n, run, [&](std::size_t begin, std::size_t end) {
    std::sort(at(v, begin), at(v, end), less);
  });
  std::vector<T> merged(n);
  // Each round doubles the sorted runs' length: about log2(n / run) rounds.
  for (std::size_t width = run; width < n; width *= 2) {
    const std::size_t pairs = (n + 2 * width - 1) / (2 * width);
    parallel_for_chunks(threads, pairs, 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t p = begin; p < end; ++p) {
        const std::size_t lo = 2 * width * p, mid = std::min(n, lo + width), hi = std::min(n, lo + 2 * width);
        std::merge(at(v, lo), at(v, mid), at(v, mid), at(v, hi), at(merged, lo), less);
      }
    });
    v.swap(merged);
  }
}

}  // namespace sm
