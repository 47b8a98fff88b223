// Recombination of a face's triangles into quadrangles (Gmsh's Recombine Surface): pairs
// of triangles sharing an edge become one quadrangle. Two choices of pairs, as
// Mesh.RecombinationAlgorithm: Simple (0, Gmsh's greedy pass in quality order) and
// Matching (1, in Gmsh the Blossom IV minimum-cost perfect matching; here the greedy
// pairs, then augmenting paths of the dual graph that pair the triangles left, see
// docs/kernel.md).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "exact/quality.h"
#include "mesh/mesh_constraints.h"

namespace sm {

struct RecombineOptions {
  RecombineAlgorithm algorithm = RecombineAlgorithm::Matching;
  /// A pair whose quadrangle's corner quality (exact/quality.h's quad_quality) is below this stays two
  /// triangles (Gmsh splits back its quadrangles below 0.1 of its own measure).
  double min_quality = 0.1;
  /// Matching: triangles one augmenting-path search may visit (bounds the work on a
  /// face whose unpaired triangles are far apart).
  std::uint32_t max_search = 4096;
};

struct RecombineResult {
  std::vector<std::array<std::uint32_t, 3>> triangles;   // the triangles left unpaired
  std::vector<std::array<std::uint32_t, 4>> quads;       // oriented as their triangles
  std::uint64_t augmentations = 0;                       // Matching's augmenting paths
};

/// Pairs the consistently oriented `triangles` (node indices into `xyz` and `plane`).
/// Only convex quadrangles are formed (decided with orient2d on the `plane` points, the
/// face's parameter plane); edges listed in `fixed` (node pairs, smaller first, sorted:
/// embedded curves) are kept. Deterministic: ties go by triangle index.
RecombineResult recombine(std::span<const std::array<std::uint32_t, 3>> triangles, std::span<const Vec3> xyz,
                          std::span<const Vec2> plane, std::span<const std::pair<std::uint32_t, std::uint32_t>> fixed,
                          const RecombineOptions& opt);

}  // namespace sm
