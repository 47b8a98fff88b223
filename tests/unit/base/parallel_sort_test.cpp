#include "base/parallel_sort.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

using namespace sm;

TEST_CASE("parallel_sort: sorted as std::sort sorts, the same bytes for every thread count") {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> key(0, 999);
  // Pairs ordered by their first member only: equal keys with different seconds show
  // that the order among equals does not depend on the thread count either.
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{100}, std::size_t{1000},
                              std::size_t{1025}, std::size_t{50000}}) {
    std::vector<std::pair<int, int>> input(n);
    for (std::size_t i = 0; i < n; ++i) input[i] = {key(rng), static_cast<int>(i)};
    const auto by_key = [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first < b.first; };
    std::vector<std::pair<int, int>> one = input;
    parallel_sort(1, one, by_key, 64);   // runs of 64: several merge rounds
    CHECK(std::is_sorted(one.begin(), one.end(), by_key));
    std::vector<std::pair<int, int>> expected = input;
    std::sort(expected.begin(), expected.end());
    std::vector<std::pair<int, int>> got = one;
    std::sort(got.begin(), got.end());
    CHECK(got == expected);   // a permutation of the input
    for (const int threads : {2, 3, 8}) {
      std::vector<std::pair<int, int>> many = input;
      parallel_sort(threads, many, by_key, 64);
      CHECK(many == one);
    }
  }
}
