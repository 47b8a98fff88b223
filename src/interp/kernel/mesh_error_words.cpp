// The mesh kernel's problems worded by the diagnostic table (mesh_error_words.h).
#include "interp/kernel/mesh_error_words.h"

#include <optional>
#include <type_traits>

namespace sm::interp {

using lang::Diag;
using lang::DiagFormat;

namespace {

using Worded = std::pair<Diag, std::string>;

template <class... Args>
Worded worded(std::type_identity_t<DiagFormat<Args...>> kind, const Args&... args) {
  return {kind.kind(), lang::format_diag<Args...>(kind, args...)};
}

// A problem whose sentence ends with its place: lon/lat on a geometry, else x, y, z.
template <class... Args>
Worded placed(const MeshError& e, std::type_identity_t<DiagFormat<Args..., double, double>> on_sphere,
              std::type_identity_t<DiagFormat<Args..., double, double, double>> in_space, const Args&... args) {
  if (e.has_lonlat) return worded<Args..., double, double>(on_sphere, args..., e.where.lon, e.where.lat);
  return worded<Args..., double, double, double>(in_space, args..., e.xyz.x, e.xyz.y, e.xyz.z);
}

// The problems of one curve or of the $Periodic links and merged meshes (no surface first).
std::optional<Worded> worded_curve_problem(const MeshError& e) {
  const int c = e.tag(0);
  const auto& n = e.numbers;
  switch (e.problem) {
    case MeshProblem::LayerEndCurved: return worded(Diag::MeshLayerEndCurved, c, n[0]);
    case MeshProblem::LayersTouch: return worded(Diag::MeshLayersTouch, n[0], c);
    case MeshProblem::CurveNoGeometry: return worded(Diag::MeshCurveNoGeometry, c);
    case MeshProblem::CurveNoEndPoint: return worded(Diag::MeshCurveNoEndPoint, c);
    case MeshProblem::CurveSizeNotFinite: return worded(Diag::MeshCurveSizeNotFinite, c);
    case MeshProblem::RepairRoundsExhausted: return worded(Diag::MeshRepairRoundsExhausted, n[0]);
    case MeshProblem::RepairCurveTooFewPoints: return worded(Diag::MeshRepairCurveTooFewPoints, n[0]);
    case MeshProblem::RepairPointOutOfRange: return worded(Diag::MeshRepairPointOutOfRange, n[0], n[1], n[2]);
    case MeshProblem::RepairNoPointAtParameter: return worded(Diag::MeshRepairNoPointAtParameter, n[0], e.value);
    case MeshProblem::RepairTriangulationFailed: return worded(Diag::MeshRepairTriangulationFailed, e.reason);
    case MeshProblem::RepairEdgeRecoveryFailed: return worded(Diag::MeshRepairEdgeRecoveryFailed, e.reason);
    case MeshProblem::PeriodicSourceNotMeshed: return worded(Diag::MeshPeriodicSourceNotMeshed, n[0], n[1]);
    case MeshProblem::PeriodicCopyNotAlong: return worded(Diag::MeshPeriodicCopyNotAlong, n[0], n[1], n[2], n[3]);
    case MeshProblem::PeriodicCycle: return worded(Diag::MeshPeriodicCycle, n[0], n[1]);
    case MeshProblem::PeriodicCurveNodeCounts: return worded(Diag::MeshPeriodicCurveNodeCounts, n[0], n[1], n[2], n[3]);
    case MeshProblem::PeriodicSurfaceNodeCounts:
      return worded(Diag::MeshPeriodicSurfaceNodeCounts, e.surface, n[0], n[1], n[2], n[4], n[3]);
    case MeshProblem::PeriodicSurfaceNotCopy: return worded(Diag::MeshPeriodicSurfaceNotCopy, e.surface, n[0]);
    case MeshProblem::PeriodicSurfacePointNoNode:
      return worded(Diag::MeshPeriodicSurfacePointNoNode, e.surface, n[0], n[1]);
    case MeshProblem::DiscreteCurveChanged: return worded(Diag::MeshDiscreteCurveChanged, n[0], n[1], n[2]);
    default: break;
  }
  return std::nullopt;
}

// The problems of a face's boundary, plane, layers and triangulation.
std::optional<Worded> worded_face_problem(const MeshError& e) {
  const int s = e.surface;
  const auto& n = e.numbers;
  switch (e.problem) {
    case MeshProblem::GeometryMissing: return worded(Diag::MeshGeometryMissing, s, n[0]);
    case MeshProblem::LoopMissing: return worded(Diag::MeshLoopMissing, s, n[0]);
    case MeshProblem::CurveNotMeshed: return worded(Diag::MeshCurveNotMeshed, s, n[0]);
    case MeshProblem::LoopNotConnected: return worded(Diag::MeshLoopNotConnected, s, n[0], n[1]);
    case MeshProblem::LoopTooFewNodes:
      return placed(e, Diag::MeshLoopTooFewNodes, Diag::MeshLoopTooFewNodesXyz, s, n[0]);
    case MeshProblem::LoopNotClosed: return worded(Diag::MeshLoopNotClosed, s, n[0]);
    case MeshProblem::NoBoundaryLoop: return worded(Diag::MeshNoBoundaryLoop, s);
    case MeshProblem::EmbeddedPointNoNode: return worded(Diag::MeshEmbeddedPointNoNode, s, n[0]);
    case MeshProblem::EmbeddedCurveNotMeshed: return worded(Diag::MeshEmbeddedCurveNotMeshed, s, n[0]);
    case MeshProblem::FaceAtPole: return placed(e, Diag::MeshFaceAtPole, Diag::MeshFaceAtPoleXyz, s, e.value);
    case MeshProblem::FaceNoArea: return placed(e, Diag::MeshFaceNoArea, Diag::MeshFaceNoAreaXyz, s, e.value);
    case MeshProblem::FaceNotPlanar: return placed(e, Diag::MeshFaceNotPlanar, Diag::MeshFaceNotPlanarXyz, s, e.value);
    case MeshProblem::FacePointOffPlane:
      return placed(e, Diag::MeshFacePointOffPlane, Diag::MeshFacePointOffPlaneXyz, s, e.value);
    case MeshProblem::LayersOverlap: return placed(e, Diag::MeshLayersOverlap, Diag::MeshLayersOverlapXyz, s);
    case MeshProblem::LayersOpen: return placed(e, Diag::MeshLayersOpen, Diag::MeshLayersOpenXyz, s);
    case MeshProblem::LayersFill: return worded(Diag::MeshLayersFill, s);
    case MeshProblem::DelaunayFailed: return worded(Diag::MeshDelaunayFailed, s, e.reason);
    case MeshProblem::BoundaryNodesCoincide:
      return placed(e, Diag::MeshBoundaryNodesCoincide, Diag::MeshBoundaryNodesCoincideXyz, s, n[0], n[1]);
    case MeshProblem::RecoveryFailed: return worded(Diag::MeshRecoveryFailed, s, e.reason);
    case MeshProblem::BoundaryEdgesCross:
      return placed(e, Diag::MeshBoundaryEdgesCross, Diag::MeshBoundaryEdgesCrossXyz, s, n[0], n[1]);
    case MeshProblem::BoundaryNodeOnEdge:
      return placed(e, Diag::MeshBoundaryNodeOnEdge, Diag::MeshBoundaryNodeOnEdgeXyz, s, n[0]);
    case MeshProblem::HoleRemovalFailed: return worded(Diag::MeshHoleRemovalFailed, s, e.reason);
    case MeshProblem::RefinementFailed: return worded(Diag::MeshRefinementFailed, s, e.reason);
    case MeshProblem::MeshAdaptFailed: return worded(Diag::MeshAdaptFailed, s, e.reason);
    default: break;
  }
  return std::nullopt;
}

// The problems of a transfinite, extruded or periodic (copied) face.
std::optional<Worded> worded_copied_face_problem(const MeshError& e) {
  const int s = e.surface;
  const auto& n = e.numbers;
  switch (e.problem) {
    case MeshProblem::TransfiniteHoles:
      if (n[0] == 1) return worded(Diag::MeshTransfiniteHole, s);
      return worded(Diag::MeshTransfiniteHoles, s, n[0]);
    case MeshProblem::TransfiniteCorner: return worded(Diag::MeshTransfiniteCorner, s, n[0]);
    case MeshProblem::TransfiniteCornerCount:
      if (n[0] == 1) return worded(Diag::MeshTransfiniteOneCorner, s);
      return worded(Diag::MeshTransfiniteCorners, s, n[0]);
    case MeshProblem::TransfiniteCornerOffBoundary: return worded(Diag::MeshTransfiniteCornerOffBoundary, s);
    case MeshProblem::TransfiniteCornerTwice: return worded(Diag::MeshTransfiniteCornerTwice, s);
    case MeshProblem::TransfiniteSidesUnequal4:
      return worded(Diag::MeshTransfiniteSidesUnequal4, s, n[0], n[1], n[2], n[3]);
    case MeshProblem::TransfiniteSidesUnequal3: return worded(Diag::MeshTransfiniteSidesUnequal3, s, n[0], n[1]);
    case MeshProblem::TransfiniteEmptySide: return worded(Diag::MeshTransfiniteEmptySide, s);
    case MeshProblem::SourceNotMeshed: return worded(Diag::MeshSourceNotMeshed, s, n[0]);
    case MeshProblem::ExtrudeTopNodes: return worded(Diag::MeshExtrudeTopNodes, s, n[0], n[1], n[2], n[3]);
    case MeshProblem::ExtrudeSweptElements: return worded(Diag::MeshExtrudeSweptElements, s, n[0], n[1]);
    case MeshProblem::ExtrudeCurveNotCopy: return worded(Diag::MeshExtrudeCurveNotCopy, s, n[0], n[1]);
    case MeshProblem::ExtrudeNodeNoCopy: return worded(Diag::MeshExtrudeNodeNoCopy, s, n[0]);
    case MeshProblem::PairedCurvesNoNodes: return worded(Diag::MeshPairedCurvesNoNodes, s);
    case MeshProblem::PeriodicFaceCurveNodes:
      return worded(Diag::MeshPeriodicFaceCurveNodes, s, n[0], n[1], n[2], n[4], n[3]);
    case MeshProblem::PeriodicNodeOffCurves:
      return worded(Diag::MeshPeriodicNodeOffCurves, s, e.xyz.x, e.xyz.y, e.xyz.z, n[0]);
    case MeshProblem::PeriodicQuadNodeOffCurves: return worded(Diag::MeshPeriodicQuadNodeOffCurves, s, n[0]);
    default: break;
  }
  return std::nullopt;
}

}  // namespace

std::pair<Diag, std::string> worded_mesh_problem(const MeshError& e) {
  if (std::optional<Worded> w = worded_curve_problem(e)) return *w;
  if (std::optional<Worded> w = worded_face_problem(e)) return *w;
  if (std::optional<Worded> w = worded_copied_face_problem(e)) return *w;
  return worded(Diag::MeshNoProblemNamed);
}

}  // namespace sm::interp
