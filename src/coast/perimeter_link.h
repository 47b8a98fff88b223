// Linking of cut shoreline chains along a closed perimeter (a region box, a region
// polygon, a patch box): the one rule region.cpp, region_polygon.cpp and patch.cpp share.
//
// Every chain is oriented with the "filled" side (ocean for a region, land for a patch)
// on its left, and lies either inside or outside the perimeter, its ends on it (perimeter
// parameter t, counter-clockwise, in [0, period)). Along the perimeter the filled side is
// known from the ends: inside, the filled part runs counter-clockwise from a chain's last
// point to the next chain's first point; outside, from a first point counter-clockwise to
// the next last point. The perimeter is a boundary where exactly one side is filled; it is
// walked with the filled side on the left (counter-clockwise when that is the inside).
#pragma once

#include <cstddef>
#include <vector>

namespace sm::coast {

struct PerimeterChain {
  double t_first = -1, t_last = -1;   // perimeter parameters of its ends (< 0: not on the perimeter)
  bool outside = false;               // lies outside the perimeter
};

enum class PerimeterLinkError {
  None,
  Inconsistent,   // two chains of one side enter (or leave) in a row: orientations disagree
  NoBoundary,     // a chain end meets no boundary along the perimeter (both sides filled or both empty)
};

struct PerimeterLink {
  /// For each chain with its last point on the perimeter: the chain whose first point the
  /// perimeter walk from there reaches, and the direction of that walk.
  std::vector<std::size_t> next;
  std::vector<char> ccw;
  PerimeterLinkError error = PerimeterLinkError::None;
  std::size_t bad_chain = 0;   // with an error: the chain it was found at
};

/// `inside_filled` / `outside_filled`: the filled state of a side without any chain end on
/// it. Ties in t are ordered last points first, then by chain index, so that a chain
/// leaving and one entering at the same point link with a zero-length walk. Loops run
/// over the 2n ends a bounded number of times: O(n log n).
PerimeterLink link_along_perimeter(const std::vector<PerimeterChain>& chains, bool inside_filled = false,
                                   bool outside_filled = false);

}  // namespace sm::coast
