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
        for (std::uint32_t j = 0, n_l = static_cast<std::uint32_t>(polys[l].size()); j < n_l; ++j) {
          const Vec2 a = polys[l][j], b = polys[l][next(j, n_l)];
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
    make_fine_grids();
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
    return any_segment_near(lo, hi, [&f](std::uint32_t l, std::uint32_t, Vec2 s0, Vec2 s1) { return f(l, s0, s1); });
  }
  /// As any_near, f(l, j, s0, s1) told the segment's polygon l and its number j there.
  template <class F>
  bool any_segment_near(Vec2 lo, Vec2 hi, F&& f) {
    if (entries_.empty()) return false;
    ++stamp_;
    const auto [x0, y0] = at(lo);
    const auto [x1, y1] = at(hi);
    auto visit = [&](const std::pair<std::uint32_t, std::uint32_t>* b,
                     const std::pair<std::uint32_t, std::uint32_t>* e) {
      for (; b != e; ++b) {
        const auto [l, j] = *b;
        std::uint32_t& mark = seen_[first_[l] + j];
        if (mark == stamp_) continue;
        mark = stamp_;
        ++visited_;
        const auto& p = polys_[l];
        if (f(l, j, p[j], p[next(j, static_cast<std::uint32_t>(p.size()))])) return true;
      }
      return false;
    };
    for (std::uint32_t y = y0; y <= y1; ++y)
      for (std::uint32_t x = x0; x <= x1; ++x) {
        const std::size_t c = std::size_t{y} * side_ + x;
        const auto fine =
            std::lower_bound(fine_.begin(), fine_.end(), c, [](const Fine& g, std::size_t k) { return g.cell < k; });
        if (fine == fine_.end() || fine->cell != c) {
          if (visit(entries_.data() + start_[c], entries_.data() + start_[c + 1])) return true;
          continue;
        }
        const auto [fx0, fy0] = fine_at(*fine, lo);
        const auto [fx1, fy1] = fine_at(*fine, hi);
        for (std::uint32_t fy = fy0; fy <= fy1; ++fy)
          for (std::uint32_t fx = fx0; fx <= fx1; ++fx) {
            const std::size_t k = fine->first + std::size_t{fy} * fine->side + fx;
            if (visit(fine_entries_.data() + fine_start_[k], fine_entries_.data() + fine_start_[k + 1])) return true;
          }
      }
    return false;
  }
  /// Segments handed to f so far, over every query (what a query costs).
  std::size_t visited() const { return visited_; }

 private:
  // Segment j's end vertex, (j + 1) mod n without a division: a grid's build takes every
  // segment's twice, and the integer division was a visible part of it.
  static std::uint32_t next(std::uint32_t j, std::uint32_t n) { return j + 1 == n ? 0 : j + 1; }
  std::pair<std::uint32_t, std::uint32_t> at(Vec2 p) const {
    auto c = [&](double v, double o) {
      return static_cast<std::uint32_t>(std::clamp((v - o) / cell_, 0.0, static_cast<double>(side_ - 1)));
    };
    return {c(p.x, lo_.x), c(p.y, lo_.y)};
  }
  // A cell holding more than kDense entries (where the coast is dense in (u,v): near the
  // map's centre a cell of the world's grid is 200 km across, 60 segments at 3 km) gets a
  // grid of its own over its entries' box; a query looks in the fine cells its box covers
  // there. A point's fine cell comes from the same monotone arithmetic (clamped) for a
  // segment's box and a query's, so a point of both lies in a fine cell of both ranges, as
  // for the coarse cells.
  static constexpr std::uint32_t kDense = 32;
  struct Fine {
    std::size_t cell;           // the coarse cell
    Vec2 lo;                    // its entries' box's lower corner
    double size;                // a fine cell's side
    std::uint32_t side;         // fine cells per side
    std::size_t first;          // its first fine cell in fine_start_
  };
  std::pair<std::uint32_t, std::uint32_t> fine_at(const Fine& g, Vec2 p) const {
    auto c = [&](double v, double o) {
      return static_cast<std::uint32_t>(std::clamp((v - o) / g.size, 0.0, static_cast<double>(g.side - 1)));
    };
    return {c(p.x, g.lo.x), c(p.y, g.lo.y)};
  }
  void make_fine_grids() {
    std::size_t cells = 0;
    for (std::size_t c = 0; c + 1 < start_.size(); ++c) {
      const std::size_t m = start_[c + 1] - start_[c];
      if (m <= kDense) continue;
      const auto side = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(m)), 2.0, 256.0));
      Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
      for (std::size_t e = start_[c]; e < start_[c + 1]; ++e) {
        const auto [l, j] = entries_[e];
        for (const Vec2 x : {polys_[l][j], polys_[l][next(j, static_cast<std::uint32_t>(polys_[l].size()))]})
          lo = {std::min(lo.x, x.x), std::min(lo.y, x.y)}, hi = {std::max(hi.x, x.x), std::max(hi.y, x.y)};
      }
      fine_.push_back({c, lo, std::max({hi.x - lo.x, hi.y - lo.y, 1e-300}) / side, side, cells});
      cells += std::size_t{side} * side;
    }
    if (fine_.empty()) return;
    fine_start_.assign(cells + 1, 0);
    auto each_fine_cell = [&](auto&& f) {
      for (const Fine& g : fine_)
        for (std::size_t e = start_[g.cell]; e < start_[g.cell + 1]; ++e) {
          const auto [l, j] = entries_[e];
          const Vec2 a = polys_[l][j], b = polys_[l][next(j, static_cast<std::uint32_t>(polys_[l].size()))];
          const auto [x0, y0] = fine_at(g, {std::min(a.x, b.x), std::min(a.y, b.y)});
          const auto [x1, y1] = fine_at(g, {std::max(a.x, b.x), std::max(a.y, b.y)});
          for (std::uint32_t y = y0; y <= y1; ++y)
            for (std::uint32_t x = x0; x <= x1; ++x) f(g.first + std::size_t{y} * g.side + x, entries_[e]);
        }
    };
    each_fine_cell([&](std::size_t k, std::pair<std::uint32_t, std::uint32_t>) { ++fine_start_[k + 1]; });
    for (std::size_t k = 1; k < fine_start_.size(); ++k) fine_start_[k] += fine_start_[k - 1];
    SM_ASSERT(fine_start_.back() < 0xFFFFFFFFu,
              "SegmentGrid: more fine cell entries than 32-bit offsets (coast/segment_grid.h)");
    fine_entries_.resize(fine_start_.back());
    std::vector<std::uint32_t> fill(fine_start_.begin(), fine_start_.end() - 1);
    each_fine_cell([&](std::size_t k, std::pair<std::uint32_t, std::uint32_t> en) { fine_entries_[fill[k]++] = en; });
  }
  const std::vector<std::vector<Vec2>>& polys_;
  Vec2 lo_{0, 0};
  double cell_ = 1;
  std::uint32_t side_ = 0, stamp_ = 0;
  std::vector<std::uint32_t> start_;   // cell c's entries: entries_[start_[c] .. start_[c + 1])
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries_;   // (polygon, segment)
  std::vector<std::uint32_t> seen_;
  std::vector<std::size_t> first_;
  std::vector<Fine> fine_;                                              // by coarse cell
  std::vector<std::uint32_t> fine_start_;                               // as start_, per fine cell
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fine_entries_;   // as entries_
  std::size_t visited_ = 0;
};

}  // namespace sm::coast
