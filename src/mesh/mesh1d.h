// 1D meshing of a model (paper section 3.2, docs/fields.md): each curve is discretised
// so that its edges follow the size field on the surface, N from the integral of |X'|/h,
// then the paper's self-intersection repair (Delaunay of all 1D nodes + edge recovery).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "base/progress.h"
#include "field/boundary_layer.h"
#include "field/field.h"
#include "field/size_policy.h"
#include "geo/model.h"
#include "mesh/mesh_constraints.h"
#include "mesh/mesh_error.h"
#include "mesh/model_mesh.h"

namespace sm {

struct Mesh1dOptions {
  field::SizePolicyOptions size;                 ///< Mesh.MeshSize* (docs/fields.md)
  const field::SizeField* background = nullptr;  ///< Background Field, if any
  double bbox_diag = 0;        ///< Gmsh's CTX::lc; <= 0: the model's bounding-box diagonal
  int min_curve_nodes = 3;     ///< Mesh.MinimumCurveNodes (splines, B-splines, Bezier)
  int min_circle_nodes = 7;    ///< Mesh.MinimumCircleNodes (full turn of an arc)
  /// Adaptive trapezoid: an interval is halved while its trapezoid and its two halves
  /// differ by more than rel * (its integral) + abs (in elements). Nodes sit at whole
  /// elements of the integral, so a thousandth of an element per interval moves none of
  /// them visibly; where the size has kinks (ChannelWidth's widths, clamps) a tighter abs
  /// halved such intervals down to 1e-5 of an element: the World Ocean's 1D took 2.2
  /// times as long at 1e-5 (0.71 s against 0.32 s) for 8 more nodes in 11,209.
  double rel_tolerance = 1e-4;
  double abs_tolerance = 1e-3;
  /// Mesh.SmoothRatio: along each curve the size may grow by at most sqrt(ratio) - 1 per
  /// unit length (Gmsh's smoothing of the primitive); <= 1 disables it.
  double smooth_ratio = 1.8;
  bool repair_intersections = true;  ///< the paper's section 3.2 repair loop
  /// Which curves the repair sees: those bounding or embedded in a surface (what the 2D
  /// mesher needs; Gmsh's 1D mesh of free curves ignores crossings), or every curve.
  bool repair_all_curves = false;
  std::uint32_t max_repair_rounds = 200;
  /// Mesh.MaxElements: once every curve's size integral is known (before any node is
  /// placed), a curve, or all curves together, asking for more nodes than this is a
  /// LimitExceeded error naming the curve; <= 0: no limit (counts are still refused
  /// beyond kMaxCurveNodes).
  double max_elements = 0;
  /// With max_elements set and more than coarse_check_nodes nodes asked in all, called
  /// before the nodes are placed with a coarse 1D mesh (each curve at most
  /// kCoarseCurveNodes nodes at equal increments of its size integral, no repair), so
  /// that the caller can estimate the faces' triangles without paying for the full 1D
  /// mesh; returning false stops meshing (kind Stopped, the caller holds the reason).
  /// From 10^4 nodes: the boundary triangulation of a face with that many nodes on
  /// straight sides already takes a second (5e4: 20 s).
  std::function<bool(const ModelMesh& coarse)> coarse_check;
  double coarse_check_nodes = 1e4;
  /// Threads over curves (Mesh.MaxNumThreads1D, else General.NumThreads); <= 0: the
  /// hardware's. Each curve's integral and nodes are computed on their own and the nodes
  /// numbered in tag order afterwards, so the mesh is the same bytes for any count. The
  /// background field is called from these threads (SizeField is thread-safe).
  int threads = 1;
  /// Reports stage "1D" (one unit per curve) and "1D repair" (no total); null: silent.
  /// Called on the calling thread only.
  Progress* progress = nullptr;
  /// Transfinite curves (their node counts and laws, transfinite_curve.h) and the
  /// recombined surfaces: with Mesh.RecombinationAlgorithm 1 a curve that is not
  /// transfinite and bounds a recombined surface (any surface with Mesh.RecombineAll)
  /// gets an odd node count, as in Gmsh 4.8.4 (an even number of boundary edges lets the
  /// matching pair every triangle). Null: none.
  const MeshConstraints* constraints = nullptr;
  /// `BoundaryLayer Field = n;`: a straight curve not in a field's CurvesList that leaves
  /// one of its PointsList points gets the layer heights as its first nodes there (Gmsh
  /// 4.8.4's meshGEdge.cpp), the rest of it meshed as before; null: none.
  const std::vector<field::BoundaryLayerParams>* boundary_layers = nullptr;
};

/// The integrand's size h(t) along one curve: for `t`, the curve jets at t, sets h (> 0).
using CurveSizeFn =
    std::function<void(std::span<const double> t, std::span<const geo::Jet3> jets, std::span<double> h)>;

/// Samples of the primitive a(t) = integral_0^t |X'(s)| / h(s) ds (adaptive trapezoid,
/// piece by piece, sizes evaluated in batches): t and a increasing, t from 0 to 1. With
/// smooth_ratio > 1 the sizes at the samples are first limited as Gmsh does (dh/ds <=
/// sqrt(smooth_ratio) - 1, forward and backward sweeps until stable).
struct CurvePrimitive {
  std::vector<double> t, a;
  std::uint64_t evaluations = 0;
  double total() const { return a.empty() ? 0.0 : a.back(); }
};

CurvePrimitive integrate_curve(const geo::Curve& c, const CurveSizeFn& size, double rel_tolerance = 1e-4,
                               double abs_tolerance = 1e-3, double smooth_ratio = 0);

/// Most nodes one curve may get: node indices are 32-bit.
inline constexpr double kMaxCurveNodes = 2147483647.0;

/// Nodes per curve of the coarse mesh given to Mesh1dOptions::coarse_check.
inline constexpr int kCoarseCurveNodes = 64;

/// Gmsh's node count N = max(min_segments + 1, int(a + 1.99)) as a double: not finite
/// for a primitive that is not, possibly beyond what can be placed.
double node_count(const CurvePrimitive& p, int min_segments);

/// The parameters of the node_count() nodes at equal increments a/(N-1) of the
/// primitive (first 0, last 1); with max_nodes > 0 at most that many (a coarse version).
/// Empty when the count is not finite or over kMaxCurveNodes (callers check node_count).
std::vector<double> place_nodes(const CurvePrimitive& p, int min_segments, int max_nodes = 0);

/// The parameters of exactly n >= 2 nodes at equal increments of the primitive.
std::vector<double> place_n_nodes(const CurvePrimitive& p, int n);

/// Minimum number of segments of a curve (Gmsh's minimumMeshSegments): 1 for lines,
/// MinimumCurveNodes - 1 for splines, a share of MinimumCircleNodes for arcs.
int min_segments(const geo::Curve& c, const Mesh1dOptions& opt);

struct Mesh1dStats {
  std::uint64_t curves = 0, nodes = 0, edges = 0;
  std::uint64_t size_evaluations = 0;   // points at which the size was evaluated
  std::uint32_t repair_rounds = 0, repair_splits = 0;
  double seconds_integrate = 0, seconds_repair = 0;
};

struct Mesh1dResult {
  ModelMesh mesh;
  /// A failure names the curve (both curves of a crossing: entities of dimension 1).
  MeshError error;
  Mesh1dStats stats;
  bool ok() const { return error.ok(); }
};

/// Meshes every model vertex and curve (in tag order, deterministic). On failure the
/// result holds the error and no usable mesh.
Mesh1dResult mesh_curves(const geo::Model& model, const Mesh1dOptions& opt);

}  // namespace sm
