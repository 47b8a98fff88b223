// The ocean loops of a region from the shoreline chains its boundary cuts: the one walk
// region.cpp (a box) and region_polygon.cpp (a polygon) share; only the piece of boundary
// between two chains is the region's own.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>
#include "coast/region.h"

namespace sm::coast {

/// Closes `chains` (each with `ring` and `pts`, land on the left) into loops with the ocean
/// on the left: a chain reversed, then, where the next chain (`next`, from
/// link_along_perimeter in perimeter_link.h) does not start where this one ends,
/// `boundary(c, nc)`, the region's boundary piece from chain c's first point to chain nc's
/// last point. Appends the loops to `loops`; returns the chain whose walk does not come
/// back to it, if any. Each step marks one chain used, so the walk takes at most
/// chains.size() steps in all.
template <class Chain, class BoundaryPiece>
std::optional<std::size_t> close_region_loops(const std::vector<Chain>& chains, const std::vector<std::size_t>& next,
                                              BoundaryPiece&& boundary, std::vector<RegionLoop>& loops) {
  std::vector<char> used(chains.size(), 0);
  for (std::size_t c0 = 0; c0 < chains.size(); ++c0) {
    if (used[c0]) continue;
    RegionLoop loop;
    std::size_t c = c0;
    while (!used[c]) {
      used[c] = 1;
      RegionPiece coast;
      coast.ring = chains[c].ring;
      coast.pts.assign(chains[c].pts.rbegin(), chains[c].pts.rend());   // ocean on the left
      const std::size_t nc = next[c];
      const geo::LonLat from = chains[c].pts.front(), to = chains[nc].pts.back();
      loop.pieces.push_back(std::move(coast));
      if (!(from.lon == to.lon && from.lat == to.lat)) loop.pieces.push_back(boundary(c, nc));
      c = nc;
    }
    if (c != c0) return c0;
    loops.push_back(std::move(loop));
  }
  return std::nullopt;
}

}  // namespace sm::coast
