// segment_distance2 (coast/segment_distance.h), the deviation bound's point-to-segment
// measure that divides only when the foot falls inside: the same bits as the model that
// divides every time, on random segments of an Earth-sized sphere and at the cases where
// the shortcut's comparisons tie (a point at an end, on the planes through the ends, a
// zero-length segment, signed zeros).
#include "coast/segment_distance.h"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace sm;
using namespace sm::coast;

namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Checks the shortcut against the model at p; counts where each branch was taken.
struct Checker {
  std::size_t before = 0, after = 0, inside = 0, checked = 0;
  void operator()(const Vec3& p, const Vec3& a, const Vec3& ab) {
    const double l2 = norm2(ab);
    const double got = segment_distance2(p, a, ab, l2), want = segment_distance2_model(p, a, ab, l2);
    if (std::isnan(want)) {
      CHECK(std::isnan(got));
    } else {
      CHECK(bits(got) == bits(want));
    }
    const double num = dot(p - a, ab);
    if (l2 > 0 && num <= 0) ++before;
    else if (l2 > 0 && num >= l2) ++after;
    else ++inside;
    ++checked;
  }
};

}  // namespace

TEST_CASE("segment distance: the same bits as dividing every time, on random segments") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), len(-2e4, 2e4), off(-6e4, 6e4);
  const double R = 6371000.0;
  Checker check;
  for (int i = 0; i < 200000; ++i) {
    Vec3 c{unit(rng), unit(rng), unit(rng)};
    const double n = norm(c);
    if (!(n > 0.1)) continue;
    c = (R / n) * c;
    const Vec3 a = c, ab{len(rng), len(rng), len(rng)};
    const Vec3 p = c + Vec3{off(rng), off(rng), off(rng)};
    check(p, a, ab);
    // The ends themselves and points along the segment's line (the foot at 0, 1 and
    // beyond: the comparisons' ties).
    check(a, a, ab);
    check(a + ab, a, ab);
    const double s = 4 * unit(rng) - 1.5;
    check(a + s * ab, a, ab);
    // On the plane through an end at right angles to the segment: dot(p - a, ab) near 0
    // or near l2, with rounding either side.
    const Vec3 side{ab.y, -ab.x, 0.0};
    check(a + 1e-3 * unit(rng) * side, a, ab);
    check(a + ab + 1e-3 * unit(rng) * side, a, ab);
    check(p, a, Vec3{0, 0, 0});   // a zero-length segment
  }
  CHECK(check.before > 100000);
  CHECK(check.after > 100000);
  CHECK(check.inside > 100000);
}

TEST_CASE("segment distance: signed zeros, tiny and non-finite inputs") {
  Checker check;
  const double z[] = {0.0, -0.0, 1e-310, -1e-310, 1.0, -1.0, 3.0};
  for (double px : z)
    for (double ax : z)
      for (double bx : z)
        for (double by : z) {
          check(Vec3{px, -0.0, 0.0}, Vec3{ax, 0.0, -0.0}, Vec3{bx, by, -0.0});
          check(Vec3{px, by, 1e-300}, Vec3{ax, -0.0, 0.0}, Vec3{bx, 0.0, by});
        }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  check(Vec3{nan, 0, 0}, Vec3{0, 0, 0}, Vec3{1, 0, 0});
  check(Vec3{1, 0, 0}, Vec3{0, 0, 0}, Vec3{nan, 0, 0});
  CHECK(check.checked == 2 * 7 * 7 * 7 * 7 + 2);
}
