// The one failure shape of the mesh kernel (1D and 2D meshers): a kind, the problem with
// its typed values (numbers, a place, a sub-step's reason), the model entities involved
// (the interpreter maps them back to the statements that created them, as it does for
// geo/error.h); never thrown, never printed: the interpreter words each problem
// (interp/kernel/mesh_error_words.cpp).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "base/vec.h"
#include "geo/sphere.h"

namespace sm {

/// LimitExceeded: more nodes or triangles than Mesh.MaxElements (or kMaxCurveNodes);
/// Stopped: Mesh1dOptions::coarse_check said no.
enum class MeshErrorKind { None, Failed, Intersection, DuplicatePoint, Invalid, NoProgress, LimitExceeded, Stopped };

/// A model entity named by an error: its dimension (1 curve, 2 surface) and tag.
struct MeshEntity {
  int dim = 0;
  int tag = 0;
  friend bool operator==(MeshEntity a, MeshEntity b) { return a.dim == b.dim && a.tag == b.tag; }
};

/// What failed, beside the kind: each member lists the values it fills. "surface" is
/// MeshError::surface (the face as meshed: a compound's union keeps its own tag), n0..n3 are
/// MeshError::numbers, "place" MeshError::xyz (with has_lonlat/where on a sphere geometry),
/// "reason" MeshError::reason (a sub-step's own words). The kinds Intersection,
/// DuplicatePoint, LimitExceeded and Stopped need no problem (None).
enum class MeshProblem {
  None,
  // 1D: the curve is entities[0].
  LayerEndCurved,      ///< n0 the point where a boundary layer ends, on a curve that is no line
  LayersTouch,         ///< n0 the point where two boundary layers end
  CurveNoGeometry,     ///< the curve has no shape
  CurveNoEndPoint,     ///< an end point of the curve does not exist
  CurveSizeNotFinite,  ///< the curve's size integral is not finite
  // The 1D crossing repair (mesh/boundary_recovery.h) failing other than on a crossing.
  RepairRoundsExhausted,      ///< n0 the repair rounds run
  RepairCurveTooFewPoints,    ///< n0 the curve given fewer than two points
  RepairPointOutOfRange,      ///< n0 the curve, n1 the point index, n2 the points there are
  RepairNoPointAtParameter,   ///< n0 the curve; value the parameter of the split
  RepairTriangulationFailed,  ///< reason: the triangulation's words
  RepairEdgeRecoveryFailed,   ///< reason: the edge recovery's words
  PeriodicSourceNotMeshed,    ///< n0 the periodic curve, n1 its source curve, which has no mesh
  PeriodicCopyNotAlong,       ///< n0 the periodic curve, n1 its source, n2 the node, n3 the nodes' count less one
  PeriodicCycle,              ///< n0 the periodic curve, n1 its source, not meshed first
  // After meshing: the $Periodic links (mesh/periodic_curve.h) or the merged surfaces.
  PeriodicCurveNodeCounts,     ///< n0 the periodic curve, n1 its nodes, n2 its source curve, n3 the source's nodes
  PeriodicSurfaceNodeCounts,   ///< surface, n0 its curve, n1 its nodes, n2 the source's curve, n3 that one's nodes, n4
                               ///< the source surface
  PeriodicSurfaceNotCopy,      ///< surface, n0 the source surface
  PeriodicSurfacePointNoNode,  ///< surface, n0 its embedded point, n1 the source's paired point
  DiscreteCurveChanged,        ///< n0 the discrete curve, n1 its mesh nodes, n2 the nodes its file gave
  // 2D: the surface is MeshError::surface (and entities[0]).
  GeometryMissing,         ///< n0 the surface geometry that does not exist
  LoopMissing,             ///< n0 the curve loop that does not exist
  CurveNotMeshed,          ///< n0 the curve of a loop with no 1D mesh
  LoopNotConnected,        ///< n0 the loop, n1 the curve (signed) where it breaks
  LoopTooFewNodes,         ///< n0 the loop; place
  LoopNotClosed,           ///< n0 the loop
  NoBoundaryLoop,          ///< no loop at all
  EmbeddedPointNoNode,     ///< n0 the embedded point
  EmbeddedCurveNotMeshed,  ///< n0 the embedded curve
  // The face's plane (mesh/face_plane.h); value: the share of its size Gmsh's check allows.
  FaceAtPole,                    ///< a lon/lat Sphere face reaching a pole; place
  FaceNoArea,                    ///< the outer loop encloses no area; place
  FaceNotPlanar,                 ///< the boundary is not planar; place
  FacePointOffPlane,             ///< an embedded point is off the plane; place
  LayersOverlap,                 ///< the boundary layers overlap; place
  LayersOpen,                    ///< the layers leave a part with no closed boundary; place
  LayersFill,                    ///< the layers fill the face
  DelaunayFailed,                ///< reason: the boundary nodes' Delaunay's words
  BoundaryNodesCoincide,         ///< n0, n1 the two nodes at one place; place
  RecoveryFailed,                ///< reason: the edge recovery's words
  BoundaryEdgesCross,            ///< n0, n1 the curves of the crossing edges; place
  BoundaryNodeOnEdge,            ///< n0 the curve of the edge a node lies on; place
  HoleRemovalFailed,             ///< reason: the hole removal's words
  RefinementFailed,              ///< reason: the refinement's words
  MeshAdaptFailed,               ///< reason: meshadapt's words
  TransfiniteHoles,              ///< n0 the holes of a transfinite surface
  TransfiniteCorner,             ///< n0 the corner point not on the boundary
  TransfiniteCornerCount,        ///< n0 the corners, not 3 or 4 (mesh/transfinite_surface.h)
  TransfiniteCornerOffBoundary,  ///< a corner off the boundary chain
  TransfiniteCornerTwice,        ///< a corner listed twice
  TransfiniteSidesUnequal4,      ///< n0..n3 the divisions: third side, first, fourth, second
  TransfiniteSidesUnequal3,      ///< n0, n1 the divisions: first side, third
  TransfiniteEmptySide,          ///< a side with no edge
  SourceNotMeshed,               ///< n0 the surface an extrusion or periodic copy copies, not meshed
  ExtrudeTopNodes,               ///< n0 the top curve, n1 its nodes, n2 the source curve, n3 its nodes
  ExtrudeSweptElements,          ///< n0 the source curve, n1 the layers' elements
  ExtrudeCurveNotCopy,           ///< n0 the top's curve, n1 the curve it should copy
  ExtrudeNodeNoCopy,             ///< n0 the source surface
  PairedCurvesNoNodes,           ///< a periodic copy's paired curves have no nodes
  PeriodicFaceCurveNodes,        ///< as PeriodicSurfaceNodeCounts, met while copying the face
  PeriodicNodeOffCurves,         ///< n0 the source surface; place (always in space): its node on no paired curve
  PeriodicQuadNodeOffCurves,     ///< n0 the source surface
};

struct MeshError {
  MeshErrorKind kind = MeshErrorKind::None;
  /// The failing entity first (the curve of a 1D error, the surface of a 2D one), then
  /// the others involved (the second curve of a crossing, the curves of a surface's
  /// crossing boundary edges); each once.
  std::vector<MeshEntity> entities;
  MeshProblem problem = MeshProblem::None;
  int surface = 0;                      ///< a 2D problem: the face as meshed
  std::array<long long, 5> numbers{};   ///< the problem's numbers (MeshProblem)
  double value = 0;                     ///< the problem's one real number (MeshProblem)
  std::string reason;                   ///< a sub-step's own words (MeshProblem)
  bool has_xyz = false;      ///< a 2D problem with a place
  Vec3 xyz;                  ///< where, in space (when known)
  bool has_lonlat = false;   ///< on a sphere geometry: where, in degrees
  geo::LonLat where;
  double count = 0;          ///< LimitExceeded: the nodes or triangles asked
  double limit = 0;          ///< LimitExceeded: the limit they exceed
  bool all_curves = false;   ///< 1D LimitExceeded: count is the sum over the curves

  bool ok() const { return kind == MeshErrorKind::None; }
  /// The tag of entities[i], 0 when there is none.
  int tag(std::size_t i = 0) const { return i < entities.size() ? entities[i].tag : 0; }
  /// Appends an entity unless it is already named (tags <= 0 name nothing).
  void add_entity(int dim, int tag) {
    const MeshEntity e{dim, tag};
    if (tag <= 0) return;
    for (const MeshEntity& x : entities)
      if (x == e) return;
    entities.push_back(e);
  }
};

}  // namespace sm
