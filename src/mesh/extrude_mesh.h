// The structured mesh of entities made by `Extrude {...} {...; Layers{...}; [Recombine;]}`
// (Gmsh 4.8.4's meshGEdgeExtruded.cpp / meshGFaceExtruded.cpp, read for their meaning): a
// swept curve gets one node per layer element at the extrusion's fractions, a top copy the
// nodes of its source moved to the top, a swept surface the grid of its source curve's
// nodes by the layers (quadrangles with Recombine, else each cell cut into two triangles;
// a cell that closes on the rotation axis is a triangle), a top surface its source's
// elements moved to the top.
#pragma once

#include <vector>

#include "base/vec.h"
#include "geo/model.h"
#include "mesh/face_work.h"
#include "mesh/model_mesh.h"

namespace sm {

/// The nodes of curve `tag` when Extrude made it with Layers: parameters (0 first, 1 last)
/// and interior positions; false for any other curve (meshed as usual). A top copy needs
/// its source's mesh in `mesh` already (its tag is lower: curves are numbered in order).
bool extruded_curve_nodes(const geo::Model& model, const ModelMesh& mesh, int tag, std::vector<double>& ts,
                          std::vector<Vec3>& xyz);

/// Whether surface `s` is meshed by mesh_extruded_face.
bool is_layered_extrusion(const geo::Model& model, int surface);

/// Fills the layered surface `s` (false and f.res.error when its boundary meshes do not
/// match the layers, e.g. a swept curve merged into a curve meshed otherwise).
bool mesh_extruded_face(FaceWork& f, const geo::ModelSurface& s);

}  // namespace sm
