// Parallel refinement of a large face by domain decomposition (`-nt`): a coarse
// serial refinement, recursive coordinate bisection of its triangles into parts, part
// borders subdivided at the local size, each part refined on its own, then merged.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "mesh/refine.h"
#include "mesh/triangulation.h"

namespace sm {

/// h[i] = target size at p[i] in the plane (RefineOptions::size_at).
using PlaneSizeFn = std::function<void(std::span<const Vec2> p, std::span<double> h)>;

struct PartitionOptions {
  /// A face whose estimated triangle count is below this is refined as one piece; 0: every
  /// face is.
  std::uint64_t min_triangles = 200000;
  /// Estimated triangles per part: K = the power of two nearest estimate / this, >= 2.
  /// Small enough that 16 threads find work on a 2M-triangle face, large enough that the
  /// seams are a small share (about 4 sqrt(n) of n triangles touch a part's border).
  std::uint64_t part_triangles = 131072;
  /// The coarse refinement uses the size times this (a few thousand coarse triangles per part).
  double coarse_factor = 8;
  std::uint32_t max_parts = 4096;
  /// The size at a point depends on the point alone (a face without the extension of the
  /// boundary sizes, whose walk hint makes PlaneSizes's rounding depend on the points before):
  /// the serial steps' large batches (the coarse pass's first sizing, the cut's estimate,
  /// the border subdivision) are then evaluated in fixed chunks on the threads, each chunk by
  /// an evaluator of its own from make_size, which gives the same sizes. Set by the caller.
  bool sizes_by_point = false;
};

enum class PartRefiner { Del2d, Frontal };

struct PartitionStats {
  std::uint32_t parts = 0;
  std::uint64_t estimate = 0;             // estimated final triangles, from the coarse mesh
  std::uint64_t coarse_triangles = 0;
  std::uint64_t border_edges = 0, border_points = 0;
  RefineStats refine;                     // summed over the coarse pass and the parts
  double seconds_coarse = 0, seconds_parts = 0, seconds_merge = 0;
};

struct PartitionResult {
  std::string error;   // the first failing part's, prefixed "part k: "
  PartitionStats stats;
  bool ok() const { return error.empty(); }
};

/// x rounded to a count: 0 for x <= 0, the largest uint64 for NaN, inf or x >= 2^64 (a
/// count no mesh reaches, so budgets refuse it), never an undefined conversion.
std::uint64_t saturated_count(double x);

/// The estimated triangle count after refinement at the size: the sum over the live
/// triangles of area / (h^2 sqrt(3) / 4), 1/h^2 averaged over the edge midpoints (batched),
/// as saturated_count() (a zero or NaN size gives the largest count).
std::uint64_t estimate_triangles(const TriangleStore& m, const PlaneSizeFn& size);

/// The same estimate with the size evaluated on up to `threads` threads, in the same
/// batches, each batch by an evaluator of its own from make_size: the same count as the
/// serial one for a size that depends on the point alone (PartitionOptions::sizes_by_point).
std::uint64_t estimate_triangles(const TriangleStore& m, const std::function<PlaneSizeFn()>& make_size, int threads);

/// The part count for an estimate: the power of two nearest estimate / part_triangles,
/// at least 2 and at most max_parts. A function of the estimate only, never of threads.
std::uint32_t part_count(std::uint64_t estimate, const PartitionOptions& opt);

/// Recursive coordinate bisection: splits the points into `parts` (a power of two) sets
/// by the median of the weights along the longer extent of each set's bounding box (ties
/// by index). Returns the part of each point. Deterministic.
std::vector<std::uint32_t> bisect_parts(std::span<const Vec2> points, std::span<const double> weights,
                                        std::uint32_t parts);

/// Points strictly inside the segment a -> b spaced at the local size: the integral of
/// 1/h along it (trapezoid rule on samples at most h/4 apart) rounded to n >= 1 segments,
/// the points where the integral reaches k/n of its total. Batched size evaluations.
std::vector<Vec2> subdivide_segment(Vec2 a, Vec2 b, const PlaneSizeFn& size);

/// Refines the constrained Delaunay triangulation m of a domain (outside removed,
/// boundary and embedded edges kConstrained) in parts, on up to `threads` threads:
/// a serial del2d pass at size * coarse_factor, its triangles cut into part_count() parts
/// by bisect_parts() of their centroids weighted by their estimated final count, border
/// edges (coarse edges between parts, unless constrained) subdivided once by
/// subdivide_segment() from the smaller vertex id, each part triangulated from its coarse
/// vertices, border points and constraints (Delaunay, edge recovery, flood fill from the
/// part's side of its border) and refined with `kind` and `base` (size_at from
/// make_size(), one per part: a part never shares scratch with another), then merged in
/// part order: vertices [0, m.num_vertices()) keep their ids, the coarse vertices and
/// border points follow, then each part's new vertices; triangles in part order. Border
/// edges are ordinary (not constrained) edges of the result, which is conforming but
/// Delaunay only within parts (a later make_delaunay or smoothing fixes the seams).
/// part_sizes, if given, sets each part's size_at and vertex_size_at instead (its own
/// functions, called from the part's thread); the coarse pass never sizes by vertices.
/// The result is the same bytes for every thread count; on failure m is left empty. on_parts, if given, is called on
/// the calling thread only: (0, K) once the part count K is known, then (done, K) as parts
/// finish (non-decreasing, last (K, K) when all succeed); the parts report nothing.
PartitionResult refine_partitioned(
    TriangleStore& m, const RefineOptions& base, PartRefiner kind, const std::function<PlaneSizeFn()>& make_size,
    const PartitionOptions& opt, int threads,
    const std::function<void(std::uint32_t done, std::uint32_t parts)>& on_parts = nullptr,
    const std::function<void(RefineOptions&)>& part_sizes = nullptr);

}  // namespace sm
