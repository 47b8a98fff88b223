// Transfinite (structured) filling of a 3- or 4-sided face from its boundary nodes, with
// Gmsh 4.8.4's meaning (meshGFaceTransfinite.cpp): the corners split the boundary into
// sides, opposite sides must have the same number of edges, the interior nodes come from
// the Coons interpolation of the boundary, each grid cell is a quadrangle or two
// triangles split by the arrangement's diagonal.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/vec.h"
#include "mesh/mesh_constraints.h"

namespace sm {

/// The face's boundary as one closed chain (first node not repeated, in the loop's
/// order) and where its corners are in it.
struct TransfiniteBoundary {
  /// Interpolated coordinates of each boundary node: a plane's (u, v, 0) or points in
  /// space (the interpolation is affine, so a plane's own coordinates give its plane).
  std::vector<Vec3> coords;
  /// Space positions of each boundary node (the interpolation's u and v are the
  /// relative lengths along the first two sides, measured in space, as in Gmsh).
  std::vector<Vec3> xyz;
  /// Positions in the chain of the 3 or 4 corners, in the order written (or found).
  std::vector<std::size_t> corners;
};

/// Why a boundary cannot be filled (TransfiniteResult::numbers holds its values): not 3 or 4
/// corners (n0 the count), a corner off the chain, a corner listed twice, opposite sides
/// unequal (4 sides: n0..n3 the third side, the first, the fourth, the second; 3 sides: n0
/// the first, n1 the third), a side with no edge.
enum class TransfiniteFault {
  None,
  CornerCount,
  CornerOffBoundary,
  CornerTwice,
  SidesUnequal4,
  SidesUnequal3,
  EmptySide
};

struct TransfiniteResult {
  std::string error;                       // empty when filled: the fault in words
  TransfiniteFault fault = TransfiniteFault::None;
  std::array<int, 4> numbers{};            // the fault's values
  int L = 0, H = 0;                        // edges along the first side and the second
  /// The new interior nodes' interpolated coordinates.
  std::vector<Vec3> interior;
  /// Elements on chain positions [0, n) then new nodes n + k, oriented as the boundary
  /// chain runs (counter-clockwise for a counter-clockwise chain).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 4>> quads;
  bool ok() const { return error.empty(); }
};

/// Corners found as Gmsh finds them when none are given: the first node of each of the
/// loop's 3 or 4 curves (`curve_starts`, positions in the chain); a 3-sided face is
/// turned so that its two sides from the first corner have the same count if possible.
std::vector<std::size_t> implicit_transfinite_corners(std::span<const std::size_t> curve_starts,
                                                      std::size_t chain_size);

/// Fills the face; `smoothing` > 0 passes of elliptic smoothing on a 4-sided grid
/// (Gmsh's, with Mesh.Smoothing > 1). Errors name the counts as Gmsh reports them:
/// "cannot be meshed using the transfinite algo (divisions 4 != 5 ...)".
TransfiniteResult fill_transfinite(const TransfiniteBoundary& b, TriangleArrangement arrangement, bool quads,
                                   int smoothing = 0);

}  // namespace sm
