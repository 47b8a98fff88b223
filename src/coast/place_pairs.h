// Results that name two places of the coastline loops, (loop_a, seg_a) and (loop_b, seg_b):
// segment hits, near misses, spline overlaps. One ordering for all of them, so every
// detector returns the same list whatever order its grid visited the candidates in.
#pragma once

#include <algorithm>
#include <tuple>
#include <utility>
#include <vector>

namespace sm::coast {

/// The sort key of a pair record: (loop_a, seg_a, loop_b, seg_b).
template <class P>
auto place_pair_key(const P& p) {
  return std::tie(p.loop_a, p.seg_a, p.loop_b, p.seg_b);
}

/// Swaps the two places so that (loop_a, seg_a) <= (loop_b, seg_b).
template <class P>
void order_places(P& p) {
  if (std::pair(p.loop_b, p.seg_b) < std::pair(p.loop_a, p.seg_a)) {
    std::swap(p.loop_a, p.loop_b);
    std::swap(p.seg_a, p.seg_b);
  }
}

/// Sorts by place_pair_key.
template <class P>
void sort_place_pairs(std::vector<P>& v) {
  std::sort(v.begin(), v.end(), [](const P& a, const P& b) { return place_pair_key(a) < place_pair_key(b); });
}

}  // namespace sm::coast
