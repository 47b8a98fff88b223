// The segments of a set of closed (u,v) polygons binned on a uniform grid of the plane, so
// that a test against "every coast segment" looks only at those near its box: a closing
// round's cuts (passages.cpp) and a strait merge's two bridges (repair.cpp, handle_straits)
// each checked against the whole coast made those passes cuts x coast size (millions of
// segments at full resolution).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "base/check.h"
#include "base/vec.h"

namespace sm::coast {

class SegmentGrid {
 public:
  /// polys[l] is a closed polygon (first point not repeated); segment j of it runs from
  /// vertex j to vertex (j + 1) mod n. The polygons must outlive the grid.
  explicit SegmentGrid(const std::vector<std::vector<Vec2>>& polys) : polys_(polys) {
    std::size_t n = 0;
    lo_ = {1e300, 1e300};
    Vec2 hi{-1e300, -1e300};
    for (const auto& p : polys)
      for (Vec2 x : p) {
        lo_ = {std::min(lo_.x, x.x), std::min(lo_.y, x.y)};
        hi = {std::max(hi.x, x.x), std::max(hi.y, x.y)};
        ++n;
      }
    if (n == 0) return;
    // About one segment per cell on average. The cells are one array of offsets into one
    // of entries (4 bytes a cell, where a vector per cell took 24 and an allocation).
    side_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(n)), 1.0, 2048.0));
    cell_ = std::max({hi.x - lo_.x, hi.y - lo_.y, 1e-300}) / side_;
    start_.assign(static_cast<std::size_t>(side_) * side_ + 1, 0);
    auto each_cell = [&](auto&& f) {
      for (std::uint32_t l = 0; l < polys.size(); ++l)
        for (std::uint32_t j = 0; j < polys[l].size(); ++j) {
          const Vec2 a = polys[l][j], b = polys[l][(j + 1) % polys[l].size()];
          const auto [x0, y0] = at({std::min(a.x, b.x), std::min(a.y, b.y)});
          const auto [x1, y1] = at({std::max(a.x, b.x), std::max(a.y, b.y)});
          for (std::uint32_t y = y0; y <= y1; ++y)
            for (std::uint32_t x = x0; x <= x1; ++x) f(std::size_t{y} * side_ + x, l, j);
        }
    };
    std::size_t total = 0;
    each_cell([&](std::size_t c, std::uint32_t, std::uint32_t) { ++start_[c + 1], ++total; });
    SM_ASSERT(total < 0xFFFFFFFFu, "SegmentGrid: more cell entries than 32-bit offsets (coast/segment_grid.h)");
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    entries_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    each_cell([&](std::size_t c, std::uint32_t l, std::uint32_t j) { entries_[fill[c]++] = {l, j}; });
    seen_.assign(n, 0);
    first_.resize(polys.size());
    for (std::size_t l = 0, k = 0; l < polys.size(); k += polys[l].size(), ++l) first_[l] = k;
  }
  /// Calls f(s0, s1) once for every segment in the cells the box [lo, hi] covers, until f
  /// says true; returns whether one did. Every segment whose box meets [lo, hi] is among
  /// them (a point of both boxes lies in a cell of both ranges).
  template <class F>
  bool any_near(Vec2 lo, Vec2 hi, F&& f) {
    return any_near_in(lo, hi, [&f](std::uint32_t, Vec2 s0, Vec2 s1) { return f(s0, s1); });
  }
  /// As any_near, f(l, s0, s1) also told the polygon l the segment belongs to.
  template <class F>
  bool any_near_in(Vec2 lo, Vec2 hi, F&& f) {
    if (entries_.empty()) return false;
    ++stamp_;
    const auto [x0, y0] = at(lo);
    const auto [x1, y1] = at(hi);
    for (std::uint32_t y = y0; y <= y1; ++y)
      for (std::uint32_t x = x0; x <= x1; ++x)
        for (std::size_t e = start_[std::size_t{y} * side_ + x], end = start_[std::size_t{y} * side_ + x + 1]; e < end;
             ++e) {
          const auto [l, j] = entries_[e];
          std::uint32_t& mark = seen_[first_[l] + j];
          if (mark == stamp_) continue;
          mark = stamp_;
          const auto& p = polys_[l];
          if (f(l, p[j], p[(j + 1) % p.size()])) return true;
        }
    return false;
  }

 private:
  std::pair<std::uint32_t, std::uint32_t> at(Vec2 p) const {
    auto c = [&](double v, double o) {
      return static_cast<std::uint32_t>(std::clamp((v - o) / cell_, 0.0, static_cast<double>(side_ - 1)));
    };
    return {c(p.x, lo_.x), c(p.y, lo_.y)};
  }
  const std::vector<std::vector<Vec2>>& polys_;
  Vec2 lo_{0, 0};
  double cell_ = 1;
  std::uint32_t side_ = 0, stamp_ = 0;
  std::vector<std::uint32_t> start_;   // cell c's entries: entries_[start_[c] .. start_[c + 1])
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries_;   // (polygon, segment)
  std::vector<std::uint32_t> seen_;
  std::vector<std::size_t> first_;
};

}  // namespace sm::coast
