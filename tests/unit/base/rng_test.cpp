// base/rng.h draws the sequences the Delaunay construction and the constrained insertion
// drew from their own copies of xorshift64* (mesh/delaunay.cpp's Rng::next, the BRIO
// shuffle and the first walk side; mesh/insert.cpp's rand3), written out here once more,
// so that a change of the generator, which would change every mesh, fails here first.
#include <doctest/doctest.h>

#include <cstdint>

#include "base/rng.h"

TEST_CASE("rng: the sequences of the former generators") {
  for (const std::uint64_t seed : {0x5DEECE66Dull, 0x2545F4914F6CDD1Dull, 0ull, 42ull}) {
    sm::Rng a(seed), b(seed);
    std::uint64_t s = seed | 1, r = seed | 1;
    for (int i = 0; i < 10000; ++i) {
      s ^= s >> 12;
      s ^= s << 25;
      s ^= s >> 27;
      REQUIRE(a.next() == static_cast<std::uint32_t>((s * 0x2545F4914F6CDD1Dull) >> 32));
      r ^= r >> 12, r ^= r << 25, r ^= r >> 27;
      const auto third = static_cast<std::uint32_t>((((r * 0x2545F4914F6CDD1Dull) >> 32) * 3) >> 32);
      const std::uint32_t got = b.below3();
      REQUIRE(got == third);
      REQUIRE(got < 3);
    }
  }
}

TEST_CASE("rng: a seed of zero still moves") {
  sm::Rng z(0);
  const std::uint32_t first = z.next();
  bool moved = false;
  for (int i = 0; i < 8; ++i) moved = moved || z.next() != first;
  CHECK(moved);
}
