// mesh/side_keys: the counting sort gives the array std::sort gives, for 1, 2 and 3 threads.
#include "mesh/side_keys.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace {

// An n x n grid of quadrangles, the left half split into triangles, its nodes numbered in
// a scrambled order (a multiplier prime to the count) from `offset`: many more elements
// than one chunk of the sort's passes, and keys placed out of order.
sm::SurfaceMesh scrambled_grid(int n, std::uint32_t offset) {
  const std::uint32_t count = static_cast<std::uint32_t>((n + 1) * (n + 1));
  auto id = [&](int i, int j) {
    const std::uint64_t k = static_cast<std::uint64_t>(j) * (n + 1) + i;
    return offset + static_cast<std::uint32_t>(k * 7919 % count);
  };
  sm::SurfaceMesh s;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i < n / 2) {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return s;
}

std::vector<sm::EdgeKey> by_std_sort(const sm::SurfaceMesh& s) {
  std::vector<sm::EdgeKey> keys;
  for (const auto& t : s.triangles)
    for (int e = 0; e < 3; ++e) keys.push_back(sm::undirected_key(t[e], t[(e + 1) % 3]));
  for (const auto& q : s.quads)
    for (int e = 0; e < 4; ++e) keys.push_back(sm::undirected_key(q[e], q[(e + 1) % 4]));
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace

TEST_CASE("sorted_side_keys: std::sort's array, repeats included, for 1, 2 and 3 threads") {
  // 300 x 300: 135,000 elements (several chunks of each pass) on 90,601 nodes (from 5);
  // and a small surface whose nodes are spread far wider than its sides (the comparison sort).
  sm::SurfaceMesh wide;
  wide.triangles = {{7, 3000000, 12}, {12, 3000000, 900000}};
  for (const sm::SurfaceMesh& s : {scrambled_grid(300, 5), scrambled_grid(3, 0), wide}) {
    const std::vector<sm::EdgeKey> expected = by_std_sort(s);
    REQUIRE(sm::side_count(s) == expected.size());
    for (int threads : {1, 2, 3}) {
      CAPTURE(threads);
      std::vector<sm::EdgeKey> keys(sm::side_count(s), 0);
      sm::sorted_side_keys(s, keys, threads);
      CHECK(keys == expected);
    }
  }
}

TEST_CASE("sorted_side_keys: an interior edge twice, a border edge once") {
  const sm::SurfaceMesh s = scrambled_grid(100, 0);
  std::vector<sm::EdgeKey> keys(sm::side_count(s));
  sm::sorted_side_keys(s, keys, 2);
  std::size_t once = 0, twice = 0;
  for (std::size_t r = 0; r < keys.size();) {
    std::size_t q = r + 1;
    while (q < keys.size() && keys[q] == keys[r]) ++q;
    (q - r == 1 ? once : twice) += 1;
    CHECK(q - r <= 2);
    r = q;
  }
  CHECK(once == 4 * 100u);                  // the grid's border
  CHECK(twice == 2u * 100 * 99 + 50 * 100);  // interior grid lines, and the triangles' diagonals
}
