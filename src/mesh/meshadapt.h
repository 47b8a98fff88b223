// meshadapt (Mesh.Algorithm 1, paper section 3.3; Geuzaine & Remacle
// 2008): local mesh modifications (split long edges, collapse short ones,
// swap for quality, smooth) until edge lengths measured in the size field
// lie within [1/sqrt2, sqrt2]. Works in the plane and in the stereographic
// plane of a PolarSphere (size delta_u = delta / lambda there).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "exact/predicates.h"
#include "mesh/triangulation.h"

namespace sm {

struct MeshAdaptOptions {
  double size = 0.1;  // uniform target edge length
  /// Optional size field, evaluated in batches (STYLE 8): h[i] = size at
  /// pts[i] (in the plane of the store: delta / lambda on the sphere).
  /// Overrides `size`. Called with the vertices whose size is not known yet.
  std::function<void(std::span<const Vec2> pts, std::span<double> h)> size_at;
  /// Rounds of split, collapse, swap and smoothing; the loop stops earlier
  /// when a round neither splits nor collapses.
  int max_iterations = 60;
  /// Smoothing sweeps per round and after the last one (Mesh.Smoothing).
  int smoothing_passes = 1;
  /// Constrained edges longer than sqrt2 are split at their midpoint only
  /// when set (right for straight boundaries; a curved one would leave its
  /// curve, so the face driver leaves it off and meshes curves in 1D).
  bool split_constrained = false;
  /// Input vertices on no constrained or hull edge (an earlier mesh's
  /// interior, to be re-adapted to a new size) may move and be collapsed
  /// when set. Off by default: such vertices are embedded points.
  bool move_input_vertices = false;
  std::uint32_t max_vertices = 0xFFFFFFF0u;
  /// Called after every pass with its name ("split", "collapse", "swap",
  /// "smooth"), for tests that run the checkers between operations.
  std::function<void(const TriangleStore& m, const char* pass)> after_pass;
};

struct MeshAdaptStats {
  std::uint32_t iterations = 0;
  std::uint64_t splits = 0, collapses = 0, collapses_refused = 0, swaps = 0, smoothed = 0;
  std::uint64_t size_evaluations = 0;
  PredicateStats predicates;
};

struct MeshAdaptResult {
  std::string error;
  MeshAdaptStats stats;
  std::vector<std::uint32_t> vertex_map;  // old -> new vertex id (kNone: removed)
  bool ok() const { return error.empty(); }
};

/// Adapts a constrained triangulation of the domain (outside triangles
/// removed, boundary edges kConstrained: the input of refine_del2d). The
/// input vertices (1D mesh, embedded points) never move and are never
/// removed (unless move_input_vertices); constrained edges are never
/// crossed or collapsed. Vertices that collapses removed are dropped at the
/// end; the ids of the input vertices are kept (with move_input_vertices
/// the ids change: vertex_map gives them). Deterministic: every pass visits edges in a fixed order.
MeshAdaptResult mesh_adapt(TriangleStore& m, const MeshAdaptOptions& opt);

}  // namespace sm
