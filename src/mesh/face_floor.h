// Step 7 of a face (face_work.h): the quality floor (Mesh2dOptions::quality_floor).
#pragma once

#include "mesh/face_work.h"

namespace sm {

/// raise_quality_floor (quality_floor.h) on f.tri with this face's curves, corners and
/// map to space, then the quality pass again where it changed something. Curve splits
/// add nodes to the curves' 1D meshes (f.mesh.curves, so faces meshed later get them);
/// a face that would end worse is put back and done again never below its starting
/// worst, else left as it was. Its report goes into f.res.notes, its counts
/// into f.res.stats. Off when opt.quality_floor <= 0.
void raise_face_floor(FaceWork& f);

}  // namespace sm
