// Cells are keyed by their level and integer coordinates in one 64-bit word and kept
// in one open-addressing table: the levels together hold at most about twice as many
// cells as there are points (each level has at most the cells of the one below),
// and a query reads at most 8 of them. The 8 cells of a brick (2 x 2 x 2 cells whose
// coordinates differ only in their lowest bits) have their home slots in one aligned
// group of 8 slots, by a hash of the brick and the cell's place in it: a query's box,
// 2 cells a side, meets 1 to 8 bricks (about 3.4 on a coast), so it reads a few
// groups of nearby slots instead of 8 random ones, with the same table.
#include "field/min_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "base/parallel.h"
#include "base/parallel_sort.h"

namespace sm::field {

namespace {

constexpr int kCoordBits = 19;
constexpr std::int64_t kCells = std::int64_t{1} << kCoordBits;  // per axis and level
constexpr int kMaxLevels = 31;                                     // level 31 is the empty key's
constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
// Relative enlargement of a query ball: covers the rounding of the ball's bounds,
// of the points' cell coordinates and of the distances the caller compares with r.
constexpr double kMargin = 1e-9;

std::int64_t cell_of(double offset, double cell) { return static_cast<std::int64_t>(std::floor(offset / cell)); }

// The largest float not above v (v itself when a float holds it; NaN stays NaN).
float float_at_most(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

// The coordinates' lowest bits in a key: a cell's place in its brick.
constexpr std::uint64_t kLaneBits =
    (std::uint64_t{1} << (2 * kCoordBits)) | (std::uint64_t{1} << kCoordBits) | std::uint64_t{1};

}  // namespace

// Inline, as key(): called for every cell a query reads (out of line, a call per cell).
inline std::size_t MinGrid::home(std::uint64_t key) const {
  const std::size_t group = static_cast<std::size_t>(((key & ~kLaneBits) * 0x9E3779B97F4A7C15ull) >> shift_) &
                            ~std::size_t{7};
  const auto lane = static_cast<std::size_t>((key & 1) | ((key >> (kCoordBits - 1)) & 2) |
                                             ((key >> (2 * kCoordBits - 2)) & 4));
  return group | lane;
}

inline std::uint64_t MinGrid::key(int level, std::int64_t i, std::int64_t j, std::int64_t k) const {
  return (static_cast<std::uint64_t>(level) << (3 * kCoordBits)) | (static_cast<std::uint64_t>(i) << (2 * kCoordBits)) |
         (static_cast<std::uint64_t>(j) << kCoordBits) | static_cast<std::uint64_t>(k);
}

MinGrid::MinGrid(std::span<const Vec3> pts, std::span<const double> value, double finest_cell, int threads) {
  if (pts.empty()) return;
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& p : pts) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  origin_ = lo;
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  scale_ = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z), std::fabs(hi.x), std::fabs(hi.y),
                     std::fabs(hi.z)}) +
           extent;
  // Every point's level-0 coordinate must stay below kCells (two cells to spare).
  finest_ = std::max(finest_cell, extent / static_cast<double>(kCells - 2));
  if (!(finest_ > 0) || !std::isfinite(finest_)) finest_ = std::max(extent, 1.0);
  // Levels up to the first whose cells are wider than twice the extent.
  levels_ = 1;
  while (levels_ < kMaxLevels && std::ldexp(finest_, levels_ - 1) <= 2 * extent) ++levels_;

  // Level 0 from the points, each further level from the cells of the one below.
  struct Cell {
    std::int64_t i, j, k;
    double min;
  };
  std::vector<Cell> level(pts.size());
  constexpr std::size_t kChunk = std::size_t{1} << 15;
  parallel_for_chunks(threads, pts.size(), kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      const Vec3 d = pts[n] - origin_;
      level[n] = {cell_of(d.x, finest_), cell_of(d.y, finest_), cell_of(d.z, finest_), value[n]};
    }
  });
  const auto same = [](const Cell& a, const Cell& b) { return a.i == b.i && a.j == b.j && a.k == b.k; };
  const auto before = [](const Cell& a, const Cell& b) {
    return std::tie(a.i, a.j, a.k) < std::tie(b.i, b.j, b.k);
  };
  std::vector<std::pair<std::uint64_t, double>> all;
  for (int l = 0; l < levels_; ++l) {
    if (l > 0)
      for (Cell& c : level) c = {c.i >> 1, c.j >> 1, c.k >> 1, c.min};
    // Cells of one key end up next to each other whatever the order among them: their
    // minimum is the same.
    parallel_sort(threads, level, before);
    std::size_t out = 0;
    for (std::size_t n = 0; n < level.size(); ++n) {
      if (out > 0 && same(level[out - 1], level[n])) {
        level[out - 1].min = std::min(level[out - 1].min, level[n].min);
      } else {
        level[out++] = level[n];
      }
    }
    level.resize(out);
    for (const Cell& c : level) all.emplace_back(key(l, c.i, c.j, c.k), c.min);
  }
  entries_ = all.size();
  std::size_t capacity = 16;
  int bits = 4;
  while (capacity < 2 * entries_) capacity *= 2, ++bits;
  shift_ = 64 - bits;
  slots_.assign(capacity, Slot{kEmpty, 0});
  // The cells inserted in the order of their home slots, so that the table is written
  // front to back: in the levels' order, a cache miss a cell was most of the grid's
  // set-up on the world's coasts. Any order gives the same answers (a key is found by
  // probing from its home slot, whatever was inserted before it).
  const auto home = [this](std::uint64_t k) { return this->home(k); };
  parallel_sort(threads, all, [&home](const std::pair<std::uint64_t, double>& a, const std::pair<std::uint64_t, double>& b) {
    const std::size_t ha = home(a.first), hb = home(b.first);
    return ha != hb ? ha < hb : a.first < b.first;
  });
  for (const auto& [k, v] : all) {
    std::size_t slot = home(k);
    while (slots_[slot].key != kEmpty) slot = (slot + 1) & (capacity - 1);
    slots_[slot] = {k, float_at_most(v)};
  }
}

double MinGrid::find(std::uint64_t k, std::size_t from) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = from;; slot = (slot + 1) & mask) {
    if (slots_[slot].key == k) return static_cast<double>(slots_[slot].min);
    if (slots_[slot].key == kEmpty) return std::numeric_limits<double>::infinity();
  }
}

bool MinGrid::box_of(const Vec3& x, double r, Box& box, double& bound) const {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  bound = std::numeric_limits<double>::infinity();
  if (slots_.empty()) return false;
  bound = kNone;
  if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z) || !(r >= 0)) return false;
  const double reach = r * (1 + kMargin) + kMargin * (scale_ + std::fabs(x.x) + std::fabs(x.y) + std::fabs(x.z));
  int l = 0;
  double cell = finest_;
  while (cell < 2 * reach) {
    if (++l >= levels_) return false;
    cell *= 2;
  }
  box.level = l;
  const double at[3] = {x.x - origin_.x, x.y - origin_.y, x.z - origin_.z};
  for (int a = 0; a < 3; ++a) {
    // Outside the indexed range a cell holds no point; clamped before the casts.
    const double lo = std::floor((at[a] - reach) / cell), hi = std::floor((at[a] + reach) / cell);
    const double top = static_cast<double>((kCells >> l) - 1);
    if (hi < 0 || lo > top) {
      bound = std::numeric_limits<double>::infinity();
      return false;
    }
    box.from[a] = static_cast<std::int64_t>(std::max(lo, 0.0));
    box.to[a] = static_cast<std::int64_t>(std::min(hi, top));
  }
  bound = std::numeric_limits<double>::infinity();
  return true;
}

template <class Fn>
bool MinGrid::each_cell(const Box& b, Fn&& fn) const {
  // The box's home slots first, each fetched as it is computed, then the probes: the
  // cache misses overlap instead of following one another. A box is at most 2 cells
  // a side but for rounding at the ball's bounds; a larger one is read as it comes.
  constexpr std::int64_t kMost = 8;
  if ((b.to[0] - b.from[0] + 1) * (b.to[1] - b.from[1] + 1) * (b.to[2] - b.from[2] + 1) <= kMost) {
    std::uint64_t keys[kMost];
    std::size_t homes[kMost];
    int n = 0;
    for (std::int64_t i = b.from[0]; i <= b.to[0]; ++i)
      for (std::int64_t j = b.from[1]; j <= b.to[1]; ++j)
        for (std::int64_t k = b.from[2]; k <= b.to[2]; ++k) {
          keys[n] = key(b.level, i, j, k);
          homes[n] = home(keys[n]);
          __builtin_prefetch(&slots_[homes[n]]);
          ++n;
        }
    for (int c = 0; c < n; ++c)
      if (!fn(find(keys[c], homes[c]))) return false;
    return true;
  }
  for (std::int64_t i = b.from[0]; i <= b.to[0]; ++i)
    for (std::int64_t j = b.from[1]; j <= b.to[1]; ++j)
      for (std::int64_t k = b.from[2]; k <= b.to[2]; ++k) {
        const std::uint64_t c = key(b.level, i, j, k);
        if (!fn(find(c, home(c)))) return false;
      }
  return true;
}

double MinGrid::lower_bound(const Vec3& x, double r) const {
  Box b;
  double low = 0;
  if (!box_of(x, r, b, low)) return low;
  each_cell(b, [&low](double m) {
    low = std::min(low, m);
    return true;
  });
  return low;
}

bool MinGrid::at_least(const Vec3& x, double r, double v) const {
  // As lower_bound's std::min, a NaN cell is passed over and nothing is at least a NaN.
  Box b;
  double low = 0;
  if (std::isnan(v)) return false;
  if (!box_of(x, r, b, low)) return low >= v;
  return each_cell(b, [v](double m) { return !(m < v); });
}

}  // namespace sm::field
