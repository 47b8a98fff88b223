// 2D meshing of a model's faces (paper section 3.3): each Plane Surface is meshed in its
// parameter plane (its own plane, a PolarSphere's stereographic (u,v), a lon/lat Sphere's
// Mercator plane) from the 1D boundary mesh: Delaunay, edge recovery, hole removal,
// refinement, smoothing, 3D output.
// The face's pipeline and the loop over faces; the options, statistics and result are in
// mesh2d_options.h, the state of one face in face_work.h, its steps in face_*.h.
#pragma once

#include <vector>

#include "geo/model.h"
#include "geo/sphere.h"
#include "mesh/mesh2d_options.h"
#include "mesh/mesh_stats.h"
#include "mesh/model_mesh.h"

namespace sm {

/// The 2D stages as named in the statistics summary ("2D boundary", "2D refine", ...).
std::vector<StageTime> stage_times(const Mesh2dStats& s);

/// Meshes every Plane Surface of the model in tag order into `mesh` (which holds the 1D
/// mesh from mesh_curves). del2d and front2d faces estimated at opt.partition.min_triangles
/// or more are refined in parts on opt.threads threads (partition.h); the result does not
/// depend on the thread count. Boundary and embedded nodes are the curve/vertex nodes, so
/// faces sharing curves share nodes; interior nodes get their (u,v) on a surface geometry.
/// Triangles are oriented with the outward normal on a sphere and by the right-hand rule
/// of the outer loop on a plane. Deterministic. On failure, surfaces meshed before the
/// failing one are kept, the failing one is absent. A filling Surface is meshed in its
/// boundary's plane when that is planar, else in its patch's parameters (face_filling.h).
Mesh2dResult mesh_surfaces(const geo::Model& model, ModelMesh& mesh, const Mesh2dOptions& opt);

/// The element budget of the faces on a coarse 1D mesh (Mesh1dOptions::coarse_check):
/// each face's estimate_triangles() on its boundary triangulation from `coarse`, against
/// opt.max_elements. Faces whose coarse boundary cannot be triangulated (coarse curves
/// may cross where the fine ones do not) are skipped: mesh_surfaces checks them on the
/// real boundary. Returns the first face over the limit as a LimitExceeded error (with
/// no warnings, statistics or meshes), or no error.
Mesh2dResult check_face_budgets(const geo::Model& model, const ModelMesh& coarse, const Mesh2dOptions& opt);

}  // namespace sm
