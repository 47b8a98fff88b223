// Step 2b of a face: the boundary layers of `BoundaryLayer Field = n;` (Gmsh 4.8.4's 2D
// boundary layers, Geo/boundaryLayersData.cpp and Mesh/meshGFace.cpp there), built
// before the face's boundary is triangulated: the rest of the face is meshed inside them.
#pragma once

#include "mesh/face_work.h"

namespace sm {

/// For each boundary or embedded edge of the face on a layer curve (the first field in
/// Mesh2dOptions::boundary_layers whose CurvesList holds it and that does not exclude the
/// face): a column of points at every node of it, along the normal into the face (at a
/// node between two layer edges the bisector of their normals; at a FanPointsList point
/// where the boundary turns away from the face, a fan of columns; where a layer ends, the
/// nodes of the curve that goes on, as Gmsh), the points at the field's layer distances
/// (field::layer_distances) from the first height at the node (SizesList, else Size).
/// Between neighbouring columns, quadrangles up to the shorter one's height, then one
/// triangle to the longer's next point; the quadrangles split into two triangles (the
/// shorter diagonal) unless the field's Quads = 1 or the face is recombined. The elements
/// go to f.layer_triangles / f.layer_quads, their new nodes to f.layer_nodes, and f.chains
/// become the boundary of the rest of the face (the edges of the layer elements not
/// shared by two of them, nor on the face's boundary); an embedded layer curve is taken
/// off f.emb_curves. False (f.fail) when the layers of the face overlap so that the rest
/// has no simple boundary. Nothing to do without fields, nor when estimating.
bool build_boundary_layers(FaceWork& f);

}  // namespace sm
