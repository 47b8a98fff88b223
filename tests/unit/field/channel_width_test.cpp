#include "field/channel_width.h"

#include <cmath>
#include <numbers>
#include <random>

#include <doctest/doctest.h>

#include "field/error.h"
#include "field/field_set.h"
#include "channel_width_brute.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;

namespace {

// A straight bank from a to b, sampled every `step`.
CoastChain cw_line(Vec3 a, Vec3 b, double step) {
  CoastChain c;
  const int n = static_cast<int>(std::ceil(norm(b - a) / step));
  for (int i = 0; i <= n; ++i) c.points.push_back(a + (static_cast<double>(i) / n) * (b - a));
  return c;
}

// A closed ring through the corners, each side sampled every `step`.
CoastChain cw_ring(const std::vector<Vec3>& corners, double step) {
  CoastChain c;
  c.closed = true;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    CoastChain side = cw_line(corners[k], corners[(k + 1) % corners.size()], step);
    c.points.insert(c.points.end(), side.points.begin(), side.points.end() - 1);
  }
  return c;
}

CoastChain cw_circle(Vec3 centre, double r, int n) {
  CoastChain c;
  c.closed = true;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    c.points.push_back(centre + Vec3{r * std::cos(t), r * std::sin(t), 0});
  }
  return c;
}

double cw_width(const ChannelWidths& w, Vec3 p) {
  double out = 0;
  w.width(std::span<const Vec3>(&p, 1), std::span<double>(&out, 1));
  return out;
}

}  // namespace

TEST_CASE("channel width: two banks of a canal 1 wide, anywhere across it") {
  ChannelWidths w({cw_line({-10, 0, 0}, {10, 0, 0}, 0.05), cw_line({-10, 1, 0}, {10, 1, 0}, 0.05)}, 50);
  for (double y : {0.5, 0.2, 0.9, 0.01}) CHECK(cw_width(w, {0.3, y, 0}) == doctest::Approx(1).epsilon(1e-6));
  // On a bank: the water side (the other side has no coast within the cap).
  CHECK(cw_width(w, {0.31, 0, 0}) == doctest::Approx(1).epsilon(1e-6));
  // Outside the canal nothing faces the bank: the search cap.
  CHECK(cw_width(w, {0, -3, 0}) == doctest::Approx(50));
}

TEST_CASE("channel width: a canal as one closed ring, 20 by 1 (the banks are one piece)") {
  ChannelWidths w({cw_ring({{-10, 0, 0}, {10, 0, 0}, {10, 1, 0}, {-10, 1, 0}}, 0.05)}, 50);
  for (double x : {-8.0, -1.0, 0.0, 3.7, 8.0}) CHECK(cw_width(w, {x, 0.5, 0}) == doctest::Approx(1).epsilon(1e-6));
  // Near a corner the two sides of the ring are neighbours (the way round is short):
  // no width below the canal's.
  CHECK(cw_width(w, {9.9, 0.05, 0}) >= 1 - 1e-9);
}

TEST_CASE("channel width: a concave bend is not a channel, a circular lake is not one either") {
  // An L-shaped coast (a right angle): the legs are one piece, the way round at most
  // sqrt(2) times the chord.
  CoastChain l = cw_line({0, 10, 0}, {0, 0, 0}, 0.05);
  CoastChain leg = cw_line({0, 0, 0}, {10, 0, 0}, 0.05);
  l.points.insert(l.points.end(), leg.points.begin() + 1, leg.points.end());
  ChannelWidths corner({l}, 50);
  CHECK(cw_width(corner, {0.5, 0.5, 0}) == doctest::Approx(50));
  ChannelWidths lake({cw_circle({0, 0, 0}, 1, 400)}, 50);
  CHECK(cw_width(lake, {0.1, 0.2, 0}) == doctest::Approx(50));
}

TEST_CASE("channel width: two islands, the strait between them and the open water beyond") {
  // Circles of radius 1 centred at x = -2 and x = 2: a strait of width 2 at the origin.
  ChannelWidths w({cw_circle({-2, 0, 0}, 1, 720), cw_circle({2, 0, 0}, 1, 720)}, 20);
  CHECK(cw_width(w, {0, 0, 0}) == doctest::Approx(2).epsilon(1e-3));
  CHECK(cw_width(w, {0.4, 0.0, 0}) == doctest::Approx(2).epsilon(1e-3));
  // Off the axis the largest ball touching the nearer island at its nearest point grows.
  const double off = cw_width(w, {0, 1.2, 0});
  CHECK(off > 2.3);
  CHECK(off < 20);
  // West of the western island: the only coast that faces the water is 4 away and
  // behind the island itself; the ball tangent there is empty up to the cap.
  CHECK(cw_width(w, {-3.5, 0, 0}) == doctest::Approx(20));
  // The field: width / ElementsAcross, clamped.
  FieldPtr f = make_channel_width_field({cw_circle({-2, 0, 0}, 1, 720), cw_circle({2, 0, 0}, 1, 720)},
                                        {/*elements_across=*/4, /*size_min=*/0.1, /*size_max=*/5});
  std::vector<Vec3> q = {{0, 0, 0}, {-3.5, 0, 0}};
  std::vector<double> h(2);
  f->eval(q, h);
  CHECK(h[0] == doctest::Approx(0.5).epsilon(1e-3));
  CHECK(h[1] == doctest::Approx(5));
}

TEST_CASE("channel width: on the sphere, a strait between two parallels of latitude") {
  // Two coasts along the parallels 10 and 10.5 degrees north on a sphere of radius
  // 6371e3: the chord between them is the strait's width.
  const double r = 6371e3, deg = std::numbers::pi / 180;
  auto parallel = [&](double lat) {
    CoastChain c;
    for (double lon = -5; lon <= 5 + 1e-9; lon += 0.01)
      c.points.push_back({r * std::cos(lat * deg) * std::cos(lon * deg), r * std::cos(lat * deg) * std::sin(lon * deg),
                          r * std::sin(lat * deg)});
    return c;
  };
  ChannelWidths w({parallel(10), parallel(10.5)}, 1e6);
  const double lat = 10.25 * deg;
  const Vec3 mid{r * std::cos(lat), 0, r * std::sin(lat)};
  const double chord = 2 * r * std::sin(0.25 * deg);
  CHECK(cw_width(w, mid) == doctest::Approx(chord).epsilon(1e-3));
}

TEST_CASE("channel width: the kind from the registry, its options and errors") {
  BuildContext ctx;
  ctx.curve_chains = [](const std::vector<int>& tags) -> std::optional<std::vector<CoastChain>> {
    std::vector<CoastChain> out;
    for (int t : tags) {
      if (t != 1 && t != 2) return std::nullopt;
      const double y = t == 1 ? 0 : 3;
      out.push_back(cw_line({-10, y, 0}, {10, y, 0}, 0.1));
    }
    return out;
  };
  FieldSet fs;
  fs.define(1, "ChannelWidth");
  fs.set(1, "CurvesList", std::vector<double>{1, 2});
  fs.set(1, "SizeMax", 100.0);
  CHECK(testing::eval1(fs, 1, {0, 1.5, 0}, ctx) == doctest::Approx(1.5).epsilon(1e-6));
  fs.set(1, "ElementsAcross", 3.0);
  CHECK(testing::eval1(fs, 1, {0, 1.5, 0}, ctx) == doctest::Approx(1).epsilon(1e-6));
  fs.set(1, "SizeMin", 1.2);
  CHECK(testing::eval1(fs, 1, {0, 1.5, 0}, ctx) == doctest::Approx(1.2));
  fs.set(1, "ElementsAcross", 0.5);
  CHECK_THROWS_AS(testing::eval1(fs, 1, {0, 1.5, 0}, ctx), FieldError);
  fs.set(1, "ElementsAcross", 2.0);
  fs.set(1, "CurvesList", std::vector<double>{1, 7});
  CHECK_THROWS_AS(testing::eval1(fs, 1, {0, 1.5, 0}, ctx), FieldError);
  fs.set(1, "CurvesList", std::vector<double>{});
  CHECK_THROWS_AS(testing::eval1(fs, 1, {0, 1.5, 0}, ctx), FieldError);
  fs.set(1, "CoastlineId", 3.0);   // no coastline_curves in the context
  CHECK_THROWS_AS(testing::eval1(fs, 1, {0, 1.5, 0}, ctx), FieldError);
}

TEST_CASE("channel width: a known water side leaves the land out, on the coast too") {
  // The islands of the test above, counter-clockwise: the water is on their right.
  std::vector<CoastChain> rings = {cw_circle({-2, 0, 0}, 1, 720), cw_circle({2, 0, 0}, 1, 720)};
  ChannelWidths both(rings, 20);
  // On the far coast of the western island, both sides count: across the island and
  // the strait to the other island (4 wide at the axis).
  CHECK(cw_width(both, {-3, 0, 0}) == doctest::Approx(4).epsilon(1e-3));
  for (CoastChain& c : rings) c.water_side = -1;
  ChannelWidths water(rings, 20);
  CHECK(cw_width(water, {-3, 0, 0}) == doctest::Approx(20));
  CHECK(cw_width(water, {0, 0, 0}) == doctest::Approx(2).epsilon(1e-3));
  CHECK(cw_width(water, {-1, 0, 0}) == doctest::Approx(2).epsilon(1e-3));
  // The wrong side declared: the strait is then "land" and reads the land width.
  for (CoastChain& c : rings) c.water_side = 1;
  ChannelWidths wrong(rings, 20);
  CHECK(cw_width(wrong, {0, 0, 0}) > 3);
}

TEST_CASE("channel width: lower() gives min(h, field) with the short search") {
  auto f = make_channel_width_field({cw_circle({-2, 0, 0}, 1, 360), cw_circle({2, 0, 0}, 1, 360)},
                                    {/*elements_across=*/2, /*size_min=*/0.05, /*size_max=*/3});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-5, 5), hs(0.01, 4);
  std::vector<Vec3> q(2000);
  std::vector<double> h(q.size()), full(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = {u(rng), u(rng), 0}, h[i] = hs(rng);
  f->eval(q, full);
  std::vector<double> low = h;
  f->lower(q, low);
  int lowered = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    CHECK(low[i] == std::min(h[i], full[i]));
    lowered += low[i] < h[i];
  }
  CHECK(lowered > 100);
}

TEST_CASE("channel width: lower() on the sphere equals min(h, field) where the grid skips the search") {
  // Two parallels of latitude 0.5 degrees apart (a strait about 55 km wide) and
  // points around them with sizes from 100 m to 300 km: the grid of smallest widths
  // rules most of them out; every result must equal the full evaluation's.
  const double r = 6371e3, deg = std::numbers::pi / 180;
  auto at = [&](double lat, double lon) {
    return Vec3{r * std::cos(lat * deg) * std::cos(lon * deg), r * std::cos(lat * deg) * std::sin(lon * deg),
                r * std::sin(lat * deg)};
  };
  std::vector<CoastChain> coast(2);
  for (double lon = -5; lon <= 5 + 1e-9; lon += 0.02)
    coast[0].points.push_back(at(10, lon)), coast[1].points.push_back(at(10.5, lon));
  auto f = make_channel_width_field(coast, {/*elements_across=*/3, /*size_min=*/200, /*size_max=*/200e3});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> lat(8, 12.5), lon(-7, 7), lh(2, 5.5);
  std::vector<Vec3> q(4000);
  std::vector<double> h(q.size()), full(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = at(lat(rng), lon(rng)), h[i] = std::pow(10.0, lh(rng));
  f->eval(q, full);
  std::vector<double> low = h;
  f->lower(q, low);
  int lowered = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    CHECK(low[i] == std::min(h[i], full[i]));
    lowered += low[i] < h[i];
  }
  CHECK(lowered > 200);
  CHECK(lowered < 3800);
}

namespace {

// Each sample's smaller width (both sides, or the water side where known), by the
// set-up's criterion over every other sample: the oracle for the tree's pruned search.
std::vector<double> brute_least_widths(const std::vector<CoastChain>& chains, double cap) {
  std::vector<double> least;
  for (const auto& [wp, wn] : brute_channel_widths(chains, cap)) least.push_back(std::min(wp, wn));
  return least;
}

}  // namespace

TEST_CASE("channel width: the pruned search gives every sample's width that all samples give") {
  // Wiggly rings and open banks, close to one another, water sides of all three kinds.
  std::mt19937 rng(20261207);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<CoastChain> chains;
  for (int c = 0; c < 12; ++c) {
    CoastChain ch;
    ch.closed = c % 3 != 0;
    ch.water_side = c % 3 - 1;
    const Vec3 centre{6 * u(rng), 6 * u(rng), 0};
    const double r = 1 + 2 * std::fabs(u(rng));
    const int n = 40 + 20 * (c % 4);
    for (int i = 0; i < n; ++i) {
      const double t = (ch.closed ? 2 : 1.2) * std::numbers::pi * i / n;
      const double rr = r * (1 + 0.15 * u(rng));
      ch.points.push_back(centre + Vec3{rr * std::cos(t), rr * std::sin(t), 0});
    }
    chains.push_back(std::move(ch));
  }
  for (double cap : {0.5, 3.0, 40.0}) {
    const std::vector<double> expected = brute_least_widths(chains, cap);
    ChannelWidths w(chains, cap);
    std::size_t k = 0, same = 0;
    for (const CoastChain& ch : chains)
      for (const Vec3& p : ch.points) same += cw_width(w, p) == expected[k++] ? 1 : 0;
    CHECK(same == expected.size());
  }
}
