// field/channel_width on several threads: each coast sample's search is its own, so the
// widths (hence the field) are the same for every thread count.
#include "field/channel_width.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

// Two wavy banks of a long canal and a row of islands in it: more samples than one
// chunk of the set-up (2048), with widths that vary from sample to sample.
std::vector<sm::field::CoastChain> threads_canal() {
  std::vector<sm::field::CoastChain> out(2);
  for (int i = 0; i <= 6000; ++i) {
    const double x = i * 0.01;
    out[0].points.push_back({x, 0.3 * std::sin(0.7 * x), 0});
    out[1].points.push_back({x, 2 + 0.4 * std::sin(0.45 * x + 1), 0});
  }
  for (int k = 0; k < 12; ++k) {
    sm::field::CoastChain c;
    c.closed = true;
    const double cx = 2 + 5 * k, cy = 1 + 0.3 * std::sin(k);
    for (int i = 0; i < 40; ++i) {
      const double t = 2 * std::numbers::pi * i / 40;
      c.points.push_back({cx + 0.2 * std::cos(t), cy + 0.15 * std::sin(t), 0});
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace

TEST_CASE("channel width threads: the same widths everywhere for 1, 2 and 7 threads") {
  std::vector<sm::Vec3> q;
  for (int i = 0; i < 600; ++i)
    for (int j = 0; j < 12; ++j) q.push_back({i * 0.1 + 0.013, -0.4 + j * 0.25, 0});
  const sm::field::ChannelWidths one(threads_canal(), 3.0, 1);
  REQUIRE(one.samples() > 12000);
  std::vector<double> w1(q.size());
  one.width(q, w1);
  // Not all at the cap: the canal and the straits beside the islands are narrower.
  std::size_t narrow = 0;
  for (double w : w1) narrow += w < 1.5 ? 1 : 0;
  CHECK(narrow > q.size() / 10);
  for (int threads : {2, 7}) {
    CAPTURE(threads);
    const sm::field::ChannelWidths many(threads_canal(), 3.0, threads);
    std::vector<double> w(q.size());
    many.width(q, w);
    CHECK(w == w1);
  }
  sm::field::ChannelWidthOptions o;
  o.elements_across = 3;
  o.size_max = 1;
  o.threads = 1;
  const auto f1 = sm::field::make_channel_width_field(threads_canal(), o);
  o.threads = 4;
  const auto f4 = sm::field::make_channel_width_field(threads_canal(), o);
  std::vector<double> h1(q.size()), h4(q.size());
  f1->eval(q, h1);
  f4->eval(q, h4);
  CHECK(h1 == h4);
}
