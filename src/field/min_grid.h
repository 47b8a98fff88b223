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
  std::uint64_t key(int level, std::int64_t i, std::int64_t j, std::int64_t k) const;
  // The cell's home slot: its brick's group of 8 slots, and its place in the brick.
  std::size_t home(std::uint64_t key) const;
  // The cell's minimum (+inf where it holds no point), probing from its home slot.
  double find(std::uint64_t key, std::size_t home) const;
  // The level and cell ranges of lower_bound(x, r); false with `bound` set where no cell
  // is read (+inf: no point that near; -inf: no bound).
  struct Box {
    int level = 0;
    std::int64_t from[3] = {0, 0, 0}, to[3] = {0, 0, 0};
  };
  bool box_of(const Vec3& x, double r, Box& box, double& bound) const;
  // Calls fn(cell minimum) for each cell of the box, in the box's order, until fn returns
  // false (then false).
  template <class Fn>
  bool each_cell(const Box& box, Fn&& fn) const;

  Vec3 origin_{};
  double finest_ = 0;
  double scale_ = 0;  // |x| + extent: the rounding margin's reference
  int levels_ = 0;
  std::size_t entries_ = 0;
  // Open addressing, linear probing; kEmpty marks a free slot. Each cell's minimum is
  // rounded down to a float: still a lower bound (half the bytes of a double, where a
  // query needs a bound and not the value), held beside its key so that a lookup reads
  // one cache line.
  struct Slot {
    std::uint64_t key;
    float min;
  };
  std::vector<Slot> slots_;
  int shift_ = 64;
};

}  // namespace sm::field
