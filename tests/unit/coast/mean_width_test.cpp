// A ring's mean width from the rope's sums (coast/mean_width.h) against the pass round the
// ring: after many random cuts and joins the sums are those of the ring within the rounding
// of two orders, the pass's width within the bounds, and every decision they are sure of
// is the pass's, including widths a few ulps from the ring's own.
#include "coast/mean_width.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

using namespace sm;
using namespace sm::coast;

namespace {

using Items = std::vector<KeptRopes::Item>;
constexpr double kRadius = 6371000.0;

// A ring of n points on a wobbly ellipse of half axes rx, ry about `centre` (far from the
// origin against its size: the shoelace terms cancel to a small area).
Items wobbly_ellipse(std::size_t n, std::uint32_t first, Vec2 centre, double rx, double ry, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  Items out;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
    const Vec2 p{centre.x + rx * (std::cos(a) + jitter(rng)), centre.y + ry * (std::sin(a) + jitter(rng))};
    out.push_back({first + static_cast<std::uint32_t>(i), p, 1.0});
  }
  return out;
}

// The three sums round the ring as passage closing once read them (point, segment, the
// closing segment last).
struct RingOrder {
  double per = 0, area2 = 0;
  double abs_area_terms = 0;
};
RingOrder ring_order(const KeptRopes& ropes, KeptRopes::Rope r) {
  std::vector<Vec2> p;
  ropes.for_each(r, [&](KeptRopes::TreeNode t) { p.push_back(ropes.uv(t)); });
  RingOrder s;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    s.per += norm(b - a);
    s.area2 += cross(a, b);
    s.abs_area_terms += std::abs(cross(a, b));
  }
  return s;
}

// Checks the rope r against the pass round its ring; counts the sure decisions.
void check_rope(const KeptRopes& ropes, KeptRopes::Rope r, std::size_t& sure, std::size_t& unsure) {
  const std::size_t n = ropes.size(r);
  const double gamma = 4.0 * static_cast<double>(n + 2) * std::numeric_limits<double>::epsilon();
  const KeptRopes::RingSums fast = ropes.ring_sums(r);
  const RingOrder slow = ring_order(ropes, r);
  REQUIRE(fast.points == n);
  // Added in tree order, the sums of the same terms (a wrong link between a subtree and
  // the point next to it, or a segment missed at a split, would be off by a whole term).
  CHECK(std::abs(fast.uv_perimeter - slow.per) <= gamma * slow.per);
  CHECK(std::abs(fast.twice_area - slow.area2) <= gamma * slow.abs_area_terms);
  const double exact = ring_mean_width_m(ropes, r, kRadius);
  const MeanWidthBounds e = bound_ring_mean_width_m(ropes, r, kRadius);
  if (!std::isfinite(e.hi)) {
    // No bound (a join's ring whose shoelace terms cancel to almost nothing): the pass decides.
    CHECK(std::abs(slow.area2) < 1e-6 * slow.abs_area_terms);
    CHECK(!mean_width_surely_below(ropes, r, kRadius, 0.5 * exact).has_value());
    unsure += 1;
    return;
  }
  CHECK(e.lo <= exact);
  CHECK(exact <= e.hi);
  // Bounds that decide all but rings near the width: the scale's range is that over the
  // ring's reach (4 at most here), so a small ring's bounds are close.
  CHECK(e.lo > 0.1 * exact);
  CHECK(e.hi < 10.0 * exact);
  if (slow.per < 0.05) CHECK(e.hi < 1.1 * e.lo);
  const double widths[] = {0.1 * exact,
                           0.5 * exact,
                           exact * (1 - 1e-3),
                           exact * (1 - 1e-6),
                           exact * (1 - 1e-13),
                           std::nextafter(exact, 0.0),
                           exact,
                           std::nextafter(exact, 2 * exact),
                           exact * (1 + 1e-13),
                           exact * (1 + 1e-6),
                           exact * (1 + 1e-3),
                           2.0 * exact,
                           10.0 * exact};
  for (double W : widths) {
    const std::optional<bool> below = mean_width_surely_below(ropes, r, kRadius, W);
    if (below) {
      CHECK(*below == (exact < W));
      ++sure;
    } else {
      ++unsure;
    }
  }
  // Far from a tie the sums decide; at the ring's own width they must not.
  CHECK(mean_width_surely_below(ropes, r, kRadius, 0.1 * exact) == std::optional<bool>(false));
  CHECK(mean_width_surely_below(ropes, r, kRadius, 10.0 * exact) == std::optional<bool>(true));
  CHECK(!mean_width_surely_below(ropes, r, kRadius, exact).has_value());
  CHECK(!mean_width_surely_below(ropes, r, kRadius, std::nextafter(exact, 2 * exact)).has_value());
}

}  // namespace

TEST_CASE("mean width: the rope's sums decide as the pass round the ring after random cuts and joins") {
  std::mt19937 rng(20261208);
  KeptRopes ropes;
  std::vector<KeptRopes::Rope> live;
  std::uint32_t next_id = 0;
  // Rings 0.01 and 0.3 (u,v) units across, 0.2 to 1.25 from the origin: each shoelace
  // term far larger than the small rings' areas.
  for (int i = 0; i < 8; ++i) {
    const double d = 0.2 + 0.15 * i, size = i % 2 == 0 ? 0.01 : 0.3;
    const Items ring = wobbly_ellipse(100 + 250 * static_cast<std::size_t>(i), next_id,
                                      {d * std::cos(i), d * std::sin(i)}, size, 0.2 * size, rng);
    next_id += static_cast<std::uint32_t>(ring.size());
    live.push_back(ropes.make(ring));
  }
  std::size_t sure = 0, unsure = 0, cuts = 0, joins = 0;
  for (int step = 0; step < 400; ++step) {
    std::uniform_int_distribution<std::size_t> pick(0, live.size() - 1);
    const std::size_t a = pick(rng);
    const std::size_t ka = ropes.size(live[a]);
    if (ka < 8) continue;
    std::uniform_int_distribution<std::size_t> pos(0, ka - 1);
    const std::size_t ja = pos(rng);
    if (step % 4 == 3 && live.size() > 1) {
      // Ring a from a1 to a0, then ring b from b1 to b0: one ring (it may cross itself; the
      // sums do not mind).
      std::size_t b = pick(rng);
      if (b == a) b = (a + 1) % live.size();
      const std::size_t kb = ropes.size(live[b]);
      const std::size_t jb = std::uniform_int_distribution<std::size_t>(0, kb - 1)(rng);
      const KeptRopes::Rope r = ropes.join(ropes.rotate(live[a], (ja + 1) % ka), ropes.rotate(live[b], (jb + 1) % kb));
      live[std::min(a, b)] = r;
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(std::max(a, b)));
      ++joins;
    } else {
      // Ring a cut at segments ja and jb: a1 ... b0 and b1 ... a0.
      const std::size_t jb = pos(rng);
      if (jb == ja) continue;
      const std::size_t from = (ja + 1) % ka, len = (jb + ka - from) % ka + 1;
      const auto [r1, r2] = ropes.split(ropes.rotate(live[a], from), len);
      live[a] = r1;
      if (ropes.size(r2) < 3) {
        ropes.release(r2);
      } else {
        live.push_back(r2);
      }
      ++cuts;
    }
    if (ropes.size(live[a < live.size() ? a : 0]) >= 3) check_rope(ropes, live[a < live.size() ? a : 0], sure, unsure);
  }
  for (KeptRopes::Rope r : live)
    if (ropes.size(r) >= 3) check_rope(ropes, r, sure, unsure);
  MESSAGE("cuts ", cuts, ", joins ", joins, "; decisions sure ", sure, ", left to the pass ", unsure);
  CHECK(cuts > 150);
  CHECK(joins > 50);
  CHECK(sure > 1000);
}

TEST_CASE("mean width: a ring's width read round it is 2|A|/P in metres at its mean point") {
  // A square 0.01 (u,v) units a side at (0.3, 0.4): |A| = 1e-4, P = 0.04, the mean point
  // at norm 0.5, so 2|A|/P = 0.005 units of 2 R / 1.25 metres.
  KeptRopes ropes;
  const Items square{{0, {0.295, 0.395}, 1}, {1, {0.305, 0.395}, 1}, {2, {0.305, 0.405}, 1}, {3, {0.295, 0.405}, 1}};
  const KeptRopes::Rope r = ropes.make(square);
  const double expected = 0.005 * 2 * kRadius / 1.25;
  CHECK(ring_mean_width_m(ropes, r, kRadius) == doctest::Approx(expected).epsilon(1e-12));
  const MeanWidthBounds b = bound_ring_mean_width_m(ropes, r, kRadius);
  CHECK(b.lo <= expected);
  CHECK(b.hi >= expected);
  CHECK(b.hi / b.lo < 1.05);   // a small ring: the scale over its reach (half its perimeter)
  const KeptRopes::RingSums s = ropes.ring_sums(r);
  CHECK(s.points == 4);
  CHECK(s.twice_area == doctest::Approx(2e-4).epsilon(1e-12));   // anticlockwise: positive
  CHECK(s.uv_perimeter == doctest::Approx(0.04).epsilon(1e-12));
  CHECK(ropes.max_norm2() == norm2(Vec2{0.305, 0.405}));
  CHECK(std::isinf(bound_ring_mean_width_m(ropes, KeptRopes::kNone, kRadius).hi));
}
