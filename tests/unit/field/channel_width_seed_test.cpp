// field/channel_width's set-up seeds each sample's search with the points that set the
// previous sample's widths (a bound that prunes the tree's cells sooner): every sample's
// two widths must still be, to the bit, the least over all other samples, on every
// chunk of samples (2048) and for every thread count.
#include "field/channel_width.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "channel_width_brute.h"

using namespace sm;
using namespace sm::field;

namespace {

// Wiggly banks and islands crowded together (channels of every width, sharp bends whose
// neighbours' answers are poor seeds), more samples than two chunks of the set-up.
std::vector<CoastChain> seed_coast(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<CoastChain> chains;
  for (int c = 0; c < 40; ++c) {
    CoastChain ch;
    ch.closed = c % 4 != 0;
    ch.water_side = c % 3 - 1;
    const Vec3 centre{8 * u(rng), 8 * u(rng), 0};
    const double r = 0.3 + 2 * std::fabs(u(rng));
    const int n = 60 + 37 * (c % 5);
    const double wobble = 0.05 + 0.3 * std::fabs(u(rng));
    for (int i = 0; i < n; ++i) {
      const double t = (ch.closed ? 2 : 1.3) * std::numbers::pi * i / n;
      const double rr = r * (1 + wobble * std::sin(5 * t + u(rng)) + 0.03 * u(rng));
      ch.points.push_back(centre + Vec3{rr * std::cos(t), rr * std::sin(t), 0});
    }
    chains.push_back(std::move(ch));
  }
  // A long canal whose banks narrow and widen: long runs where the seed is good.
  CoastChain a, b;
  for (int i = 0; i <= 1500; ++i) {
    const double x = -9 + i * 0.012;
    a.points.push_back({x, -9.5 + 0.2 * std::sin(0.9 * x), 0});
    b.points.push_back({x, -9.5 + 0.35 + 0.3 * std::sin(0.37 * x + 1), 0});
  }
  chains.push_back(std::move(a));
  chains.push_back(std::move(b));
  return chains;
}

}  // namespace

TEST_CASE("channel width seed: every sample's two widths equal the brute force's, any thread count") {
  for (const unsigned seed : {7u, 20261207u}) {
    const std::vector<CoastChain> chains = seed_coast(seed);
    for (const double cap : {0.4, 2.5, 50.0}) {
      CAPTURE(seed);
      CAPTURE(cap);
      const std::vector<std::pair<double, double>> expected = brute_channel_widths(chains, cap);
      REQUIRE(expected.size() > 2 * 2048);
      std::size_t narrow = 0;
      for (const auto& e : expected) narrow += e.first < cap || e.second < cap ? 1 : 0;
      CHECK(narrow > expected.size() / 4);  // the seeds do matter
      for (const int threads : {1, 3}) {
        CAPTURE(threads);
        const ChannelWidths w(chains, cap, threads);
        REQUIRE(w.samples() == expected.size());
        std::size_t same = 0;
        for (std::size_t i = 0; i < expected.size(); ++i) same += w.sample_widths(i) == expected[i] ? 1 : 0;
        CHECK(same == expected.size());
      }
    }
  }
}

namespace {

// Rugged coasts on the sphere (radius 6371 km): rings of random-walk radius around random
// centres, a few hundred km across, sampled every few km; islands and straits between them.
std::vector<CoastChain> seed_sphere_coast(unsigned seed, int rings) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  constexpr double kR = 6371e3;
  const auto at = [](double lat, double lon) {
    const double a = lat * std::numbers::pi / 180, b = lon * std::numbers::pi / 180;
    return Vec3{kR * std::cos(a) * std::cos(b), kR * std::cos(a) * std::sin(b), kR * std::sin(a)};
  };
  std::vector<CoastChain> chains;
  for (int c = 0; c < rings; ++c) {
    CoastChain ch;
    ch.closed = c % 5 != 0;
    ch.water_side = c % 3 - 1;
    const double lat0 = 12 * u(rng), lon0 = 12 * u(rng), r0 = 0.2 + 1.5 * std::fabs(u(rng));
    const int n = 300 + static_cast<int>(900 * std::fabs(u(rng)));
    double r = r0;
    for (int i = 0; i < n; ++i) {
      const double t = (ch.closed ? 2 : 1.5) * std::numbers::pi * i / n;
      r = std::clamp(r + 0.02 * r0 * u(rng), 0.5 * r0, 1.5 * r0);
      ch.points.push_back(at(lat0 + r * std::sin(t), lon0 + r * std::cos(t)));
    }
    chains.push_back(std::move(ch));
  }
  return chains;
}

}  // namespace

TEST_CASE("channel width seed: the seeded set-up gives the unseeded one's widths, on the sphere too") {
  const std::vector<CoastChain> flat = seed_coast(99);
  const std::vector<CoastChain> sphere = seed_sphere_coast(5, 60);
  for (const auto* chains : {&flat, &sphere}) {
    const bool on_sphere = chains == &sphere;
    for (const double cap : on_sphere ? std::vector<double>{150e3, 2e6} : std::vector<double>{1.0, 30.0}) {
      CAPTURE(on_sphere);
      CAPTURE(cap);
      const ChannelWidths old_model(*chains, cap, 2, /*seeded=*/false);
      std::size_t narrow = 0, same = 0;
      for (const int threads : {1, 2}) {
        const ChannelWidths w(*chains, cap, threads, /*seeded=*/true);
        REQUIRE(w.samples() == old_model.samples());
        for (std::size_t i = 0; i < w.samples(); ++i) {
          const auto a = w.sample_widths(i), b = old_model.sample_widths(i);
          same += a == b ? 1 : 0;
          narrow += b.first < cap || b.second < cap ? 1 : 0;
        }
      }
      CHECK(same == 2 * old_model.samples());
      CHECK(narrow > old_model.samples() / 10);
    }
  }
}

// The set-up's cost, seeded or not (CHANNEL_WIDTH_SEEDED=0), for callgrind: skipped unless
// asked for (-tc="channel width seed: cost*" --no-skip).
TEST_CASE("channel width seed: cost of the set-up" * doctest::skip()) {
  const char* env = std::getenv("CHANNEL_WIDTH_SEEDED");
  const bool seeded = env == nullptr || std::string(env) != "0";
  const ChannelWidths w(seed_sphere_coast(11, 400), 150e3, 1, seeded);
  double sum = 0;
  for (std::size_t i = 0; i < w.samples(); ++i) sum += w.sample_widths(i).first;
  MESSAGE("samples " << w.samples() << " seeded " << seeded << " sum " << sum);
  CHECK(sum > 0);
}
