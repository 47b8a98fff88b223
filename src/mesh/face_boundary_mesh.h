// Steps 3 and 4 of a face (face_work.h): the boundary mesh in the face's plane and the
// face's sizing on it.
#pragma once

#include "mesh/face_work.h"

namespace sm {

/// The local vertices (loops, embedded curves, embedded points, first occurrence order;
/// f.fixed_count of them), their Delaunay triangulation f.tri, edge recovery of f.edges
/// and hole removal; with the extension from the boundary, f.hull keeps the recovered
/// triangulation before hole removal. False (f.res.error) on duplicate nodes, crossing
/// or touching boundary edges, or a failed step.
bool triangulate_boundary(FaceWork& f);

/// f.sizing once the boundary is recovered (the plane and boundary sizes are final
/// then); consumes f.hull.
void make_sizing(FaceWork& f);

}  // namespace sm
