// Self-intersection repair of 1D meshes (the paper's section 3.2): Delaunay
// of all curve points, edge recovery; edges found crossing are split at their
// parameter midpoint (snapped on the curve by the caller) until none cross.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh/cdt.h"
#include "mesh/delaunay.h"
#include "mesh/triangulation.h"

namespace sm {

/// One discretised model curve: point indices into BoundaryProblem::points
/// with their curve parameters (increasing). A closed curve repeats its first
/// index at the end; curves sharing an end point share its index.
struct BoundaryCurve {
  std::uint32_t id = 0;  // the caller's curve tag, used in errors
  std::vector<std::uint32_t> pts;
  std::vector<double> t;
};

struct BoundaryProblem {
  std::vector<Vec2> points;  // plane or stereographic plane
  std::vector<BoundaryCurve> curves;
};

/// The point of curves[curve] at parameter t, exactly on the geometry.
using SplitFn = std::function<Vec2(std::uint32_t curve, double t)>;

struct BoundaryOptions {
  double tolerance = 1e-9;        // crossing edges shorter than this: the curves intersect
  std::uint32_t max_rounds = 200;
  DelaunayOptions delaunay;
};

enum class BoundaryErrorKind { None, Intersection, DuplicatePoint, NoProgress, Invalid };

/// What went wrong beside a crossing (the values it fills in BoundaryError): NoProgress is
/// RoundsExhausted (count: the rounds); Invalid is one of the others: a curve with fewer
/// than two points (curve_a), a point index past the points (curve_a, point_a, count), a
/// split with no point (curve_a, parameter), or the triangulation or the edge recovery
/// failing (reason: their words).
enum class BoundaryFault {
  None,
  RoundsExhausted,
  CurveTooFewPoints,
  PointOutOfRange,
  NoPointAtParameter,
  TriangulationFailed,
  EdgeRecoveryFailed
};

/// A failure located for the interpreter: the two curve ids (equal for a
/// self-intersecting curve), the place in the plane and the point indices; `message`
/// is the recovery's own sentence (its tests read it; mesh1d passes the typed values on).
struct BoundaryError {
  BoundaryErrorKind kind = BoundaryErrorKind::None;
  BoundaryFault fault = BoundaryFault::None;
  std::uint32_t curve_a = 0, curve_b = 0;
  Vec2 where;
  std::uint32_t point_a = 0, point_b = 0;
  std::size_t count = 0;    ///< RoundsExhausted: the rounds; PointOutOfRange: the points
  double parameter = 0;     ///< NoPointAtParameter: the curve parameter of the split
  std::string reason;       ///< TriangulationFailed, EdgeRecoveryFailed: the sub-step's words
  std::string message;
};

struct BoundaryResult {
  BoundaryError error;
  TriangleStore mesh;          // constrained Delaunay triangulation of all points
  std::vector<Edge> edges;     // every curve edge, constrained in mesh
  std::vector<std::uint32_t> edge_curve;  // index into curves of each edge
  std::uint32_t rounds = 0;    // Delaunay + recovery passes
  std::uint32_t splits = 0;    // edges split in total
  bool ok() const { return error.kind == BoundaryErrorKind::None; }
};

/// Repairs the discretisation in place (new points appended to
/// problem.points and inserted in the curves) until every curve edge is an
/// edge of the constrained Delaunay triangulation, or fails with a located
/// error when two crossing edges are shorter than the tolerance.
BoundaryResult recover_boundary(BoundaryProblem& problem, const SplitFn& split, const BoundaryOptions& opt = {});

}  // namespace sm
