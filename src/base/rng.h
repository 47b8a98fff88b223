// The kernel's random numbers: xorshift64* (Vigna 2016), small, fast and the same on every
// platform, so that a seeded run repeats to the byte. The Delaunay construction's BRIO
// shuffle and walk (mesh/delaunay.cpp) and the constrained insertion's walk
// (mesh/insert.cpp) draw from it.
#pragma once

#include <cstdint>

namespace sm {

class Rng {
 public:
  /// The state must not be zero: the seed's lowest bit is set.
  explicit Rng(std::uint64_t seed) : s_(seed | 1) {}

  /// The high half of the next output.
  std::uint32_t next() {
    s_ ^= s_ >> 12;
    s_ ^= s_ << 25;
    s_ ^= s_ >> 27;
    return static_cast<std::uint32_t>((s_ * 0x2545F4914F6CDD1Dull) >> 32);
  }

  /// 0, 1 or 2 from next() by a multiply, not a modulo (one draw).
  std::uint32_t below3() { return static_cast<std::uint32_t>((std::uint64_t{next()} * 3) >> 32); }

 private:
  std::uint64_t s_;
};

}  // namespace sm
