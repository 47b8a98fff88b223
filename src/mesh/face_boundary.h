// Steps 1 and 2 of a face (face_work.h): its boundary chained from the curves' 1D meshes,
// and the plane it is meshed in.
#pragma once

#include "geo/model.h"
#include "mesh/face_work.h"

namespace sm {

/// The loops' curve meshes chained into f.chains (outer first; a negative curve or loop
/// tag reverses them; a loop holding several closed chains, Gmsh's subloops, gives
/// several), the embedded points and curves into f.emb_points and f.emb_curves. A hole
/// loop with fewer than 3 nodes (an island below the mesh size) is left out with one
/// warning for the face; false (f.res.error) on a missing or open loop.
bool collect_boundary(FaceWork& f, const geo::ModelSurface& s);

/// f.plane from the collected nodes (make_face_plane: a geometry's plane, else the outer
/// loop's own plane); false when the boundary is not planar within Geometry.Tolerance.
bool choose_plane(FaceWork& f);

}  // namespace sm
