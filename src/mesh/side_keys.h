// The sides of a surface's elements as undirected edge keys in ascending order, made by a
// counting sort on each key's smaller node instead of a comparison sort, so that it is
// linear in the sides and runs on threads (the statistics' distinct edges, mesh_stats.cpp).
#pragma once

#include <cstdint>
#include <span>

#include "mesh/model_mesh.h"

namespace sm {

/// An undirected edge as one integer, its smaller node in the high half: the keys order as
/// the (smaller, larger) pairs do.
using EdgeKey = std::uint64_t;
inline EdgeKey undirected_key(std::uint32_t a, std::uint32_t b) {
  return std::uint64_t{a < b ? a : b} << 32 | (a < b ? b : a);
}
inline std::uint32_t smaller_node(EdgeKey k) { return static_cast<std::uint32_t>(k >> 32); }
inline std::uint32_t larger_node(EdgeKey k) { return static_cast<std::uint32_t>(k); }

/// The number of sides of sf's elements: 3 a triangle, 4 a quadrangle.
std::size_t side_count(const SurfaceMesh& sf);

/// Every side of sf's triangles then quadrangles (corner e to corner e + 1) as its
/// undirected_key, written to `out` (side_count(sf) keys) in ascending order: the array
/// std::sort gives, repeats included, for any `threads` (<= 1: on the calling thread).
void sorted_side_keys(const SurfaceMesh& sf, std::span<EdgeKey> out, int threads);

}  // namespace sm
