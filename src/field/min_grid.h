// Per-cell minima of a value carried by points, on nested cubic grids whose cells
// double in size level by level. It answers "can a point within r of x carry a
// value below v?" from at most 8 cells of one level, without visiting the points:
// the ChannelWidth field uses it to skip the nearest-sample query wherever no
// sample near x is narrow enough to lower the size there (field/channel_width.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/vec.h"

namespace sm::field {

class MinGrid {
 public:
  /// `value[i]` is carried by `pts[i]` (finite points). `finest_cell`: the cell size
  /// of level 0 (raised where the points' extent needs it to fit the cell index);
  /// level k has cells of finest_cell * 2^k, up to one that holds every point. The
  /// cells are sorted on `threads` threads (the same grid for every count).
  MinGrid(std::span<const Vec3> pts, std::span<const double> value, double finest_cell, int threads = 1);

  /// A lower bound on the values of the points within distance r of x: the minimum
  /// over the cells of the smallest level whose cells are at least 2r wide that
  /// meet the ball's bounding box (slightly enlarged, so that rounding never leaves
  /// a point out). +inf where no point is that near; -inf where x is not finite or
  /// the ball is wider than the coarsest level (no bound).
  double lower_bound(const Vec3& x, double r) const;
  /// lower_bound(x, r) >= v, reading the cells only until one is below v.
  bool at_least(const Vec3& x, double r, double v) const;

  std::size_t cells() const { return entries_; }

 private:
  // The level and cell ranges of lower_bound(x, r); false with `bound` set where no cell
  // is read (+inf: no point that near; -inf: no bound).
  struct Box {
    int level = 0;
    std::int64_t from[3] = {0, 0, 0}, to[3] = {0, 0, 0};
  };
  std::uint64_t key(int level, std::int64_t i, std::int64_t j, std::int64_t k) const;
  struct Brick;
  // The brick of `key` (a brick's level and coordinates), or null where no point is in it.
  const Brick* find(std::uint64_t key) const;
  // The slot where probing for `key` starts.
  std::size_t home(std::uint64_t key) const { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }
  // Calls read(cell minimum) for each cell of `box` in a brick that is held, a brick at a
  // time, until it returns false; false then. The cells of a brick not held are +inf, a
  // value that neither lowers a bound nor is below one.
  template <class Read>
  bool each_cell(const Box& box, Read&& read) const;
  bool box_of(const Vec3& x, double r, Box& box, double& bound) const;

  Vec3 origin_{};
  double finest_ = 0;
  double scale_ = 0;  // |x| + extent: the rounding margin's reference
  int levels_ = 0;
  std::size_t entries_ = 0;
  // Open addressing, linear probing; kEmpty marks a free slot. A slot holds a brick of
  // 2 x 2 x 2 cells of one level, so that a query's box of at most 2 cells a side reads
  // 1 to 8 bricks (3.4 on average for a box 2 cells wide on each axis), not 8 cells in
  // 8 random slots. Each cell's minimum is rounded down to a float: still a lower bound
  // (half the bytes of a double), +inf in a cell without points.
  //
  //   brick (level, I, J, K): cells (2I + a, 2J + b, 2K + c), lane a + 2 b + 4 c
  struct Brick {
    std::uint64_t key;
    float min[8];
  };
  std::vector<Brick> slots_;
  int shift_ = 64;
};

}  // namespace sm::field
