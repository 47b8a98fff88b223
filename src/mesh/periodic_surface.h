// `Periodic Surface` (its meaning in Gmsh 4.8.4: the target surface's mesh a copy of the
// source's): the rigid map inferred from the paired boundary curves' end points when the
// statement gives none (as Gmsh's GFace::setMeshMaster finds a translation or a rotation),
// and the correspondence of the copy's nodes with the source's ($Periodic).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "geo/model.h"
#include "mesh/mesh_constraints.h"
#include "mesh/mesh_error.h"
#include "mesh/model_mesh.h"
#include "mesh/periodic_link.h"

namespace sm {

/// The 4x4 map (16 numbers, row by row) taking each `pairs[i].first` (a source point) onto
/// `pairs[i].second` (its target) within `tolerance`: the translation when every
/// displacement agrees within `tolerance`, otherwise the rotation fitted on two independent
/// differences of points. Empty, with `why`, when all points stay in place, when the points
/// do not fix a rotation (fewer than two independent differences) or when the map found
/// misses a pair.
std::vector<double> infer_periodic_transform(const std::vector<std::pair<Vec3, Vec3>>& pairs, double tolerance,
                                             std::string* why);

/// What pairing a target surface's points and curves with a source's by a given map found
/// (Gmsh 4.8.4's setMeshMaster of a surface with a transform: boundary and embedded
/// entities alike). On success `miss` is None and every curve of the target has its
/// counterpart; otherwise `miss` says what failed and `entity` names it.
struct PeriodicSurfaceMatch {
  enum class Miss : std::uint8_t {
    None,
    Counts,  ///< the surfaces have different numbers of points or curves (`counts`)
    Point,   ///< source point `entity` lands at `image`, `distance` from the nearest target point
    Curve,   ///< target curve `entity` is the image of no source curve
  };
  std::vector<PeriodicSurfaceSpec::CurvePair> curves;
  std::vector<std::pair<int, int>> points;   // embedded points: (target, source)
  Miss miss = Miss::None;
  int entity = 0;
  Vec3 image{};
  double distance = 0;
  /// Counts: the target's points and curves, then the source's.
  std::size_t counts[4] = {0, 0, 0, 0};
};

/// Pairs surface `target`'s points and curves with surface `source`'s by `affine`: each
/// source point must land within `tolerance` of a target point, and each target curve is
/// the source curve whose end points land on its own (forward or backward); curves with the
/// same end points are told apart by their sampled bounding boxes, as Gmsh does. With
/// `embedded_only`, only the embedded points and curves (and those curves' end points) are
/// paired: the boundary's pairs are the statement's.
PeriodicSurfaceMatch match_periodic_surface(const geo::Model& model, int target, int source,
                                            const std::vector<double>& affine, double tolerance, bool embedded_only);

/// The target's node of each source node on the paired curves of a periodic surface (ends
/// included, embedded curves too) and of its paired embedded points, node for node in the
/// pair's orientation. Empty, with `why` (its PeriodicSurfaceNodeCounts), when two paired
/// curves' node counts differ (the 1D repair or a quality floor split one of them) or a
/// curve has no mesh.
std::map<std::uint32_t, std::uint32_t> periodic_boundary_images(const ModelMesh& mesh, int target,
                                                                 const PeriodicSurfaceSpec& spec, MeshError* why);

/// The $Periodic links of the periodic surfaces in tag order: each node of the copy
/// (boundary included) with its source's node, by the copy's node. A surface without a
/// mesh is left out; `why` (the first broken copy) as in periodic_boundary_images, or
/// PeriodicSurfaceNotCopy when the interiors differ.
std::vector<PeriodicLink> periodic_surface_links(const ModelMesh& mesh, const MeshConstraints& c, MeshError* why);

}  // namespace sm
