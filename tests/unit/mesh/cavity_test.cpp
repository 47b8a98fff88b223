// The refill pairing of mesh/cavity.h: on a closed boundary each edge's successor is the
// edge that starts where it ends, through the list search (short boundaries) and through
// the vertex map (long ones, the map reused and never cleared); an open boundary is
// reported, not followed past its end.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "mesh/cavity.h"

using namespace sm;

namespace {

struct RingEdge {
  std::uint32_t a, b;
};

// fan_pairs with the pairs recorded: next[i] = j.
bool successors(const std::vector<RingEdge>& ring, std::size_t keys, std::vector<std::uint32_t>& vmap,
                std::vector<std::uint32_t>& next) {
  next.assign(ring.size(), 0xFFFFFFFFu);
  return fan_pairs(
      ring, [](std::uint32_t v) { return v; }, keys, vmap,
      [&next](std::size_t i, std::size_t j) { next[i] = static_cast<std::uint32_t>(j); });
}

std::vector<RingEdge> shuffled_ring(std::uint32_t n, std::uint32_t first, std::uint64_t seed) {
  std::vector<RingEdge> ring;
  for (std::uint32_t i = 0; i < n; ++i) ring.push_back({first + i, first + (i + 1) % n});
  std::mt19937_64 rng(seed);
  std::shuffle(ring.begin(), ring.end(), rng);
  return ring;
}

}  // namespace

TEST_CASE("cavity: fan successors of short and long boundaries") {
  std::vector<std::uint32_t> vmap, next;
  for (const std::uint32_t n : {3u, 7u, 16u, 17u, 200u}) {
    const std::vector<RingEdge> ring = shuffled_ring(n, 10, n);
    REQUIRE(successors(ring, 10 + n, vmap, next));
    REQUIRE(next.size() == n);
    for (std::uint32_t i = 0; i < n; ++i) CHECK(ring[next[i]].a == ring[i].b);
  }
  // The map now holds entries of the last ring: a new long ring over other vertices must
  // not be paired through them.
  std::vector<RingEdge> open = shuffled_ring(40, 0, 1);
  for (RingEdge& e : open)
    if (e.b == 0) e.b = 150;   // ends at a vertex the last ring started an edge at
  CHECK(!successors(open, 210, vmap, next));
  std::vector<RingEdge> short_open = shuffled_ring(5, 0, 2);
  short_open.pop_back();
  CHECK(!successors(short_open, 5, vmap, next));
}
