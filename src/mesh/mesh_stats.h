// The statistics printed after meshing: nodes, triangles, quality rho = 2 r_in /
// r_circ measured in 3D, edge length over the target size, time per stage; as a summary
// for stderr and as JSON (for --stats FILE.json).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "base/vec.h"
#include "field/depth_clamp.h"
#include "mesh/model_mesh.h"
#include "mesh/time_step.h"

namespace sm {

struct StageTime {
  std::string name;
  double seconds = 0;
};

struct MeshStats {
  std::uint64_t nodes = 0, triangles = 0, edges = 0;   // nodes: those of the elements
  /// Quadrangles (transfinite or recombined surfaces) and their corner quality
  /// (exact/quality.h's quad_quality: 1 - max |90 - corner angle| / 90, in space).
  std::uint64_t quads = 0;
  double quad_min = 0, quad_mean = 0;
  double min_rho = 0, mean_rho = 0, share_rho_09 = 0;   // share of triangles with rho > 0.9
  int min_rho_surface = 0;                             // the worst triangle: its surface,
  Vec3 min_rho_at;                                     // its centroid and, set by the caller
  bool has_min_rho_lonlat = false;                     // on a sphere geometry, its lon/lat
  double min_rho_lon = 0, min_rho_lat = 0;
  bool has_sizes = false;                              // the length ratios below are set
  double len_median = 0, len_p05 = 0, len_p95 = 0;     // edge length / target size
  double share_len_07_14 = 0;                          // share of edges with ratio in [0.7, 1.4]
  std::vector<StageTime> stages;                       // filled by the caller: wall seconds
  std::vector<StageTime> stages_cpu;                   // and CPU seconds (the run's own stages only)
  TimeStep time_step;                                  // with Mesh.DepthField: set by the caller
  // With a Bathymetry depth field as Mesh.DepthField, set by the caller: the nodes MinDepth raised.
  bool has_depth_clamp = false;
  field::DepthClampReport depth_clamp;
  // With Mesh.NbPartitions (io/mesh_partition.h), set by the caller: the part count, the
  // dual-graph edges cut, the largest part over the mean, and the smallest and largest part.
  int partitions = 0;
  std::uint64_t partition_edge_cut = 0;
  double partition_imbalance = 1;
  std::uint64_t partition_min = 0, partition_max = 0;
};

/// Target size at 3D points (batched), e.g. one of Mesh2dResult::target_sizes.
using SizeAt3 = std::function<void(std::span<const Vec3>, std::span<double>)>;

/// The target size of one surface (by tag).
struct SurfaceSize {
  int surface = 0;
  SizeAt3 size;
};

/// Statistics over every surface element of the mesh (rho over the triangles, the corner
/// quality over the quadrangles). With `size`, each distinct element edge's chord length is divided by the size at its
/// midpoint (the callback may project the midpoint onto the surface).
MeshStats mesh_stats(const ModelMesh& mesh, const SizeAt3& size = nullptr);

/// As above with a target size per surface: each distinct edge is measured against the
/// size of the first surface (in tag order) that holds it and has an entry in `sizes`;
/// edges of surfaces without one are left out of the length ratios (and of `edges`).
/// The qualities and the sizes are computed on `threads` threads (<= 0: the hardware's),
/// so the size functions must be thread-safe (Mesh2dResult::target_sizes are); the
/// figures are the same for any count.
MeshStats mesh_stats(const ModelMesh& mesh, const std::vector<SurfaceSize>& sizes, int threads = 1);

/// A few lines for stderr.
std::string format_stats(const MeshStats& s);

/// The 1D mesh's figures (what `-1` prints): curves with mesh edges, the nodes on them,
/// edges, and the shortest and longest edge: great-circle arcs when every edge lies on
/// the model's sphere (metres with earth.geo, as the time step's edges), else chords in
/// model units.
struct CurveStats {
  std::size_t curves = 0, nodes = 0, edges = 0;
  double shortest = 0, longest = 0;
  bool on_sphere = false;   ///< the lengths are arcs on the sphere (metres)
};
/// With radius > 0, an edge whose two nodes lie on the sphere (centre, radius) is
/// measured along it.
CurveStats curve_stats(const ModelMesh& mesh, Vec3 centre = {}, double radius = 0);
/// "Mesh: 1204 nodes, 1198 line elements on 106 curves; edges from 412.3 to 30112 (model units)\n",
/// or "...; edges from 8.1 km to 31.4 km on the sphere\n".
std::string format_curve_stats(const CurveStats& s);
/// The same figures as one JSON object: {"nodes", "line_elements", "curves",
/// "edge_min", "edge_max", "edge_units" ("m" on the sphere, else "model"), "stages"}.
std::string curve_stats_json(const CurveStats& s, const std::vector<StageTime>& stages);
/// One JSON object (keys as the summary's words: nodes, triangles, rho_min, ...).
std::string stats_json(const MeshStats& s);

}  // namespace sm
