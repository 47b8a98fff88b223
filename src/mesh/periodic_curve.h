// `Periodic Curve` (its meaning in Gmsh 4.8.4: the target curve's mesh a copy of the source's): the
// affine maps of its Translate and Rotate forms, the check that a map takes the source's
// end points onto the target's, and the target's nodes copied from the source's mesh.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/vec.h"
#include "geo/model.h"
#include "mesh/mesh_constraints.h"
#include "mesh/mesh_error.h"
#include "mesh/model_mesh.h"

namespace sm {

/// The 4x4 map (16 numbers, row by row) of a translation by d.
std::vector<double> periodic_translation(Vec3 d);

/// The 4x4 map of a rotation by `angle` about the axis through `point` along `axis`
/// (Gmsh's computeAffineTransformation; the axis is normalised, which Gmsh leaves to the
/// script: with a unit axis the numbers are Gmsh's). Empty for a zero axis.
std::vector<double> periodic_rotation(Vec3 axis, Vec3 point, double angle);

/// The image of p by a 4x4 map (its first three rows).
Vec3 apply_affine(const std::vector<double>& affine, Vec3 p);

/// Which way `affine` takes curve `source`'s end points onto curve `target`'s, within
/// `tolerance`: +1 (begin onto begin), -1 (begin onto end), or nothing; `distances`
/// receives the two distances of the nearer pairing (for the message).
std::optional<int> periodic_orientation(const geo::Model& model, int target, int source,
                                        const std::vector<double>& affine, double tolerance,
                                        std::pair<double, double>* distances = nullptr);

/// Curve `target`'s nodes as a copy of its source's mesh (already in `mesh`): the
/// parameters `ts` (first 0, last 1, increasing) and the interior nodes' places `xyz`.
/// Without a map the parameters are the source's (reversed for orientation -1) and the
/// places the target's points there; with one, each source node is mapped and projected
/// onto the target (its parameter by a bounded search). False, with `why`
/// (PeriodicSourceNotMeshed, PeriodicCopyNotAlong), when the source has no mesh or the
/// copied parameters do not increase along the target.
bool periodic_curve_nodes(const geo::Model& model, const ModelMesh& mesh, int target, const PeriodicCurveSpec& spec,
                          std::vector<double>& ts, std::vector<Vec3>& xyz, MeshError* why);

/// The $Periodic correspondences of a meshed model, points, curves, then surfaces
/// (periodic_surface_links) in tag order: a
/// curve's nodes (ends included) with its source's in the copy's order, a point's node
/// with its master's. `why` stays ok() when every target has as many nodes as its source,
/// else it says what broke the first copy (the 1D repair splitting one of them):
/// PeriodicCurveNodeCounts, or a surface's as periodic_surface_links says.
std::vector<PeriodicLink> periodic_links(const geo::Model& model, const ModelMesh& mesh, const MeshConstraints& c,
                                         MeshError* why);

}  // namespace sm
