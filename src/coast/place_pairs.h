// Results that name two places of the coastline loops, (loop_a, seg_a) and (loop_b, seg_b):
// segment hits, near misses, spline overlaps. One ordering for all of them, so every
// detector returns the same list whatever order its grid visited the candidates in.
#pragma once

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "base/check.h"

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

/// As sort_place_pairs for distinct pairs, with no loops to number the places on
/// (renumber_for_joins' records of the loops a strait pass joined, continents' own pairs
/// among them): the records are sorted as keys and moved once, where the four-field
/// comparison moved the 40-byte records at every swap. Ties (one pair twice) keep their
/// input order, so the order is std::stable_sort's by place_pair_key.
///
/// One 64-bit key a record when the places fit: each loop named gets the span of numbers
/// 1 + its largest seg among the records, the spans laid end to end in loop order, and a
/// place (l, s) is number first[l] + s. Within a loop the numbers rise with s; a loop's
/// numbers all lie below the next named loop's first, so the numbers order as (loop, seg)
/// do, one to one. With every number below 2^32, (number_a << 32) | number_b orders as
/// (loop_a, seg_a, loop_b, seg_b). Otherwise (more than 2^32 numbers, or loop indices so
/// large that the table of firsts would outgrow the records) the two-key sort below.
template <class P>
void sort_place_pairs_by_keys(std::vector<P>& v) {
  std::vector<P> sorted;
  sorted.reserve(v.size());
  std::uint64_t max_loop = 0;
  for (const P& p : v) max_loop = std::max<std::uint64_t>({max_loop, p.loop_a, p.loop_b});
  const bool small_table = v.size() < 0xFFFFFFFFu && max_loop < 4 * std::uint64_t{v.size()} + 4096;
  std::vector<std::uint64_t> first;   // the span of loop l, then (prefix sums) its first number
  if (small_table) {
    first.assign(max_loop + 1, 0);
    for (const P& p : v) {
      first[p.loop_a] = std::max<std::uint64_t>(first[p.loop_a], std::uint64_t{p.seg_a} + 1);
      first[p.loop_b] = std::max<std::uint64_t>(first[p.loop_b], std::uint64_t{p.seg_b} + 1);
    }
    std::uint64_t total = 0;   // at most (max_loop + 1) * 2^32: no overflow
    for (std::uint64_t& f : first) {
      const std::uint64_t span = f;
      f = total;
      total += span;
    }
    if (total <= 0x100000000u) {
      std::vector<std::pair<std::uint64_t, std::uint32_t>> order(v.size());
      for (std::size_t i = 0; i < v.size(); ++i)
        order[i] = {((first[v[i].loop_a] + v[i].seg_a) << 32) | (first[v[i].loop_b] + v[i].seg_b),
                    static_cast<std::uint32_t>(i)};
      std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
      });
      for (const auto& o : order) sorted.push_back(v[o.second]);
      v = std::move(sorted);
      return;
    }
  }
  struct Key {
    std::uint64_t a, b;
    std::size_t i;
  };
  std::vector<Key> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    order[i] = {(std::uint64_t{v[i].loop_a} << 32) | v[i].seg_a, (std::uint64_t{v[i].loop_b} << 32) | v[i].seg_b, i};
  std::sort(order.begin(), order.end(), [](const Key& x, const Key& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.i < y.i;
  });
  for (const Key& k : order) sorted.push_back(v[k.i]);
  v = std::move(sorted);
}

/// As sort_place_pairs, for places on `loops` (each seg < its loop's size) that are
/// distinct pairs: the segments numbered loop after loop, (loop_a, seg_a, loop_b, seg_b)
/// orders as the two numbers do, so each record is sorted by one 64-bit key (the
/// four-field comparison over the records cost several times more). Equal keys would be one
/// pair twice; with distinct pairs the order is sort_place_pairs'.
template <class P, class Loops>
void sort_place_pairs_on(std::vector<P>& v, const Loops& loops) {
  std::vector<std::uint64_t> first(loops.size() + 1, 0);
  for (std::size_t l = 0; l < loops.size(); ++l) first[l + 1] = first[l] + loops[l].size();
  if (first.back() >= 0xFFFFFFFFu || v.size() >= 0xFFFFFFFFu) {
    sort_place_pairs(v);
    return;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    SM_ASSERT(v[i].seg_a < loops[v[i].loop_a].size() && v[i].seg_b < loops[v[i].loop_b].size(),
              "sort_place_pairs_on: a place past its loop's end (coast/place_pairs.h)");
    order[i] = {((first[v[i].loop_a] + v[i].seg_a) << 32) | (first[v[i].loop_b] + v[i].seg_b),
                static_cast<std::uint32_t>(i)};
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<P> sorted;
  sorted.reserve(v.size());
  for (const auto& o : order) sorted.push_back(v[o.second]);
  v = std::move(sorted);
}

}  // namespace sm::coast
