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

/// The target's node of each source node on the paired curves of a periodic surface (ends
/// included), node for node in the pair's orientation. Empty, with `why` (its
/// PeriodicSurfaceNodeCounts), when two paired curves' node counts differ (the 1D repair or
/// a quality floor split one of them) or a curve has no mesh.
std::map<std::uint32_t, std::uint32_t> periodic_boundary_images(const ModelMesh& mesh, int target,
                                                                 const PeriodicSurfaceSpec& spec, MeshError* why);

/// The $Periodic links of the periodic surfaces in tag order: each node of the copy
/// (boundary included) with its source's node, by the copy's node. A surface without a
/// mesh is left out; `why` (the first broken copy) as in periodic_boundary_images, or
/// PeriodicSurfaceNotCopy when the interiors differ.
std::vector<PeriodicLink> periodic_surface_links(const ModelMesh& mesh, const MeshConstraints& c, MeshError* why);

}  // namespace sm
