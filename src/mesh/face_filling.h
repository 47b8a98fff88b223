// Step 2 of a filling `Surface` not on a surface geometry (face_work.h): the plane it is
// meshed in. Gmsh 4.8.4 meshes every such face in the (u, v) of its transfinite patch
// with the metric of the map (Mesh/meshGFace.cpp). A patch whose boundary is planar (and
// that is no sphere patch) maps into that plane, so it is meshed as a Plane Surface in it,
// holes included; any other one in its patch's scaled parameters (filling_map.h).
#pragma once

#include "geo/model.h"
#include "mesh/face_work.h"

namespace sm {

/// Sets f.plane for filling surface `s` after collect_boundary(): the boundary's own plane
/// (choose_plane) when the nodes lie in one within Geometry.Tolerance and the patch has
/// no sphere, else the patch's plane, the outer loop's nodes placed from their curves'
/// parameters and every other node by projection onto the patch (its closest point).
void choose_filling_plane(FaceWork& f, const geo::ModelSurface& s);

}  // namespace sm
