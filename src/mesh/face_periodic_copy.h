// The step of a `Periodic Surface` target (face_work.h; Gmsh 4.8.4's copyMesh in meaning):
// its mesh is not made but copied from its source's, already in the model mesh.
#pragma once

#include "mesh/face_work.h"
#include "mesh/mesh_constraints.h"

namespace sm {

/// Face f.tag's mesh as a copy of spec.source's: boundary nodes from the paired
/// curves, interior nodes mapped by spec.affine (onto the surface's geometry when it has
/// one), triangles and quadrangles with the source's node order, reversed when the map
/// turns the source's boundary against the target's. False (f.fail) when the source has
/// no mesh or the paired curves' node counts differ.
bool copy_periodic_face(FaceWork& f, const PeriodicSurfaceSpec& spec);

}  // namespace sm
