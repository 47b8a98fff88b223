// exact/segments: how two closed segments meet, against integer arithmetic on a grid
// (every collinear and touching case occurs there) and on hand-picked cases.
#include "exact/segments.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>

using namespace sm;

namespace {

using K = SegmentContactKind;

std::int64_t orient_int(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
                        std::int64_t cy) {
  const std::int64_t d = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
  return (d > 0) - (d < 0);
}

// Closed segments share a point, by the textbook integer test.
bool meet_int(const std::int64_t* p, const std::int64_t* q, const std::int64_t* r, const std::int64_t* s) {
  auto on = [](const std::int64_t* a, const std::int64_t* b, const std::int64_t* c) {
    return orient_int(a[0], a[1], b[0], b[1], c[0], c[1]) == 0 && std::min(a[0], b[0]) <= c[0] &&
           c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] && c[1] <= std::max(a[1], b[1]);
  };
  const std::int64_t o1 = orient_int(p[0], p[1], q[0], q[1], r[0], r[1]);
  const std::int64_t o2 = orient_int(p[0], p[1], q[0], q[1], s[0], s[1]);
  const std::int64_t o3 = orient_int(r[0], r[1], s[0], s[1], p[0], p[1]);
  const std::int64_t o4 = orient_int(r[0], r[1], s[0], s[1], q[0], q[1]);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on(p, q, r) || on(p, q, s) || on(r, s, p) || on(r, s, q);
}

Vec2 v(const std::int64_t* a) { return {static_cast<double>(a[0]), static_cast<double>(a[1])}; }

}  // namespace

TEST_CASE("segment_contact: cross, touch at each end, overlap, disjoint") {
  CHECK(segment_contact({0, 0}, {2, 2}, {0, 2}, {2, 0}).kind == K::Cross);
  CHECK(segment_contact({0, 0}, {2, 0}, {1, 0}, {1, 3}).kind == K::Touch);
  CHECK(segment_contact({0, 0}, {2, 0}, {1, 0}, {1, 3}).end == 2);   // r on pq
  CHECK(segment_contact({0, 0}, {2, 0}, {1, 3}, {1, 0}).end == 3);   // s on pq
  CHECK(segment_contact({1, 0}, {1, 3}, {0, 0}, {2, 0}).end == 0);   // p on rs
  CHECK(segment_contact({1, 3}, {1, 0}, {0, 0}, {2, 0}).end == 1);   // q on rs
  CHECK(segment_contact({0, 0}, {1, 1}, {1, 1}, {2, 0}).kind == K::Touch);    // shared end
  CHECK(segment_contact({0, 0}, {2, 0}, {1, 0}, {3, 0}).kind == K::Overlap);
  CHECK(segment_contact({0, 0}, {1, 0}, {1, 0}, {3, 0}).kind == K::Overlap);   // collinear, one point
  CHECK(segment_contact({0, 0}, {1, 0}, {2, 0}, {3, 0}).kind == K::None);      // collinear, apart
  CHECK(segment_contact({0, 0}, {2, 0}, {0, 1}, {2, 1}).kind == K::None);      // parallel
  CHECK(segment_contact({0, 0}, {2, 2}, {3, 0}, {1.6, 1.4}).kind == K::None);  // lines cross beyond rs
  // Exact where floating point is not: c sits 1 ulp off the line through a and b.
  const double e = 0x1p-52;
  CHECK(segment_contact({0, 0}, {1, 1}, {0.5, 0.5 + e}, {1, 0}).kind == K::Cross);
  CHECK(segment_contact({0, 0}, {1, 1}, {0.5, 0.5 + e}, {0, 1}).kind == K::None);
}

TEST_CASE("segment_contact: a zero-length segment meets only where its point lies on the other") {
  // (1, 2) is inside the box of (0,0)-(4,4) but off the segment.
  CHECK(!segments_meet({1, 2}, {1, 2}, {0, 0}, {4, 4}));
  CHECK(!segments_meet({0, 0}, {4, 4}, {1, 2}, {1, 2}));
  CHECK(segments_meet({1, 1}, {1, 1}, {0, 0}, {4, 4}));
  CHECK(segments_meet({0, 0}, {4, 4}, {2, 2}, {2, 2}));
  CHECK(!segments_meet({5, 5}, {5, 5}, {0, 0}, {4, 4}));
}

TEST_CASE("segments_meet: agrees with integer arithmetic on a small grid, both orders") {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> c(0, 4);
  for (int i = 0; i < 20000; ++i) {
    std::int64_t p[2] = {c(rng), c(rng)}, q[2] = {c(rng), c(rng)}, r[2] = {c(rng), c(rng)}, s[2] = {c(rng), c(rng)};
    const bool want = meet_int(p, q, r, s);
    CHECK(segments_meet(v(p), v(q), v(r), v(s)) == want);
    CHECK(segments_meet(v(r), v(s), v(p), v(q)) == want);
    CHECK(segments_meet(v(q), v(p), v(s), v(r)) == want);
  }
}
