// A transfinite face (face_work.h): its boundary chain filled by transfinite_surface.h in
// place of steps 3 to 7.
#pragma once

#include "geo/model.h"
#include "mesh/face_work.h"
#include "mesh/mesh_constraints.h"

namespace sm {

/// Surface `s` filled as `spec` says: one boundary chain (no holes), its corners given or
/// found where the curve changes, interpolated in the face's plane (a Plane Surface) or
/// in space onto its sphere (a filling Surface), the elements oriented as output_face
/// does and stored. False (f.res.error) on holes, a corner off the boundary or a failed
/// fill.
bool mesh_transfinite_face(FaceWork& f, const geo::ModelSurface& s, const TransfiniteSurfaceSpec& spec);

}  // namespace sm
