// Delaunay triangulation of a point set by incremental Bowyer-Watson
// insertion in BRIO / Hilbert order with a visibility walk (Amenta, Choi and
// Rote 2003; Devillers, Pion and Teillaud 2002) and ghost triangles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/geometry.h"
#include "mesh/triangulation.h"

namespace sm {

struct DelaunayOptions {
  std::uint64_t seed = 0x5DEECE66Dull;  // BRIO shuffle and walk edge order: fixed, so runs repeat
};

struct DelaunayStats {
  std::uint64_t walk_steps = 0;          // triangles crossed while locating points
  std::uint64_t cavity_triangles = 0;    // triangles removed by insertions
  PredicateStats predicates;
};

/// A point equal to an earlier one: not inserted; `kept` is the vertex that
/// stands for both.
struct DuplicatePoint {
  VertexId dup, kept;
};

struct DelaunayResult {
  std::string error;  // empty on success
  std::vector<DuplicatePoint> duplicates;
  DelaunayStats stats;
  bool ok() const { return error.empty(); }
};

/// Triangulates the vertices of m (m.xy set, no triangles yet): afterwards m
/// holds the Delaunay triangulation of the distinct points, compacted, hull
/// sides with twin kNone. Exact ties are broken by vertex id, so the result
/// does not depend on the insertion order. Fails (m left without triangles)
/// when fewer than three points are not collinear.
DelaunayResult delaunay(TriangleStore& m, const DelaunayOptions& opt = {});

/// Insertion order used by delaunay(): rounds of doubling size from a seeded
/// shuffle (BRIO), each round sorted along a Hilbert curve.
std::vector<std::uint32_t> brio_order(const std::vector<Vec2>& xy, std::uint64_t seed);

/// Index along a Hilbert curve of cell (x, y) of a 2^bits x 2^bits grid
/// (bits a multiple of 4, at most 16): consecutive indices are adjacent cells.
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits);

}  // namespace sm
