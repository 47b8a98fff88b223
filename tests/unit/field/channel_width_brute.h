// The ChannelWidth set-up's criterion by brute force, for the tests of the tree's
// pruned and seeded searches (field/channel_width.cpp): every sample against every other.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

#include "field/channel_width.h"

namespace sm::field {

// Each sample's (+side, -side) widths by the set-up's criterion over every other sample
// (flat models: the normal is z), the water side's width on both sides where known.
inline std::vector<std::pair<double, double>> brute_channel_widths(const std::vector<CoastChain>& chains, double cap) {
  struct Sample {
    Vec3 p, side;
    std::size_t chain;
    double s;
  };
  std::vector<Sample> all;
  std::vector<double> length;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    const std::vector<Vec3>& q = chains[c].points;
    const std::size_t n = q.size();
    double arc = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0) arc += norm(q[k] - q[k - 1]);
      const bool wrap = chains[c].closed && n > 2;
      const Vec3 prev = k > 0 ? q[k - 1] : wrap ? q[n - 1] : q[k];
      const Vec3 next = k + 1 < n ? q[k + 1] : wrap ? q[0] : q[k];
      const Vec3 cr = cross(Vec3{0, 0, 1}, next - prev);
      all.push_back({q[k], norm(cr) > 0 ? cr / norm(cr) : Vec3{0, 0, 0}, c, arc});
    }
    length.push_back(chains[c].closed && n > 2 ? arc + norm(q.front() - q.back()) : arc);
  }
  std::vector<std::pair<double, double>> out;
  for (const Sample& a : all) {
    double wp = cap, wn = cap;
    for (const Sample& b : all) {
      const double d2 = norm2(b.p - a.p);
      if (d2 == 0 || !(d2 < cap * cap)) continue;
      const double d = std::sqrt(d2);
      if (b.chain == a.chain) {
        double along = std::fabs(b.s - a.s);
        if (chains[a.chain].closed) along = std::min(along, length[a.chain] - along);
        if (along <= std::numbers::pi / 2 * d) continue;
      }
      const double dm = dot(b.p - a.p, a.side);
      if (a.side == Vec3{0, 0, 0}) {
        wp = std::min(wp, d);
        wn = std::min(wn, d);
      } else if (dm > 0) {
        wp = std::min(wp, d2 / dm);
      } else if (dm < 0) {
        wn = std::min(wn, d2 / -dm);
      }
    }
    const int water = chains[a.chain].water_side;
    if (water > 0) wn = wp;
    if (water < 0) wp = wn;
    out.emplace_back(wp, wn);
  }
  return out;
}

}  // namespace sm::field
