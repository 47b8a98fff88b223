// The writers' settings from the script's options: node coordinates of MSH/VTK files
// (Mesh.NodeCoordinates, -coords) and the pictures' view, colours, zoom and width
// (Mesh.PictureView, PictureColour, PictureBox, PictureWorst, PictureWidth).
#pragma once

#include <string>

#include "io/mesh_model.h"
#include "io/picture.h"

namespace sm::interp {

class Interpreter;

/// Rewrites mm's node coordinates as Mesh.NodeCoordinates asks (0 xyz, 1 lon/lat, 2 the
/// stereographic plane) on the model's sphere; "" or why not.
std::string apply_node_coordinates(Interpreter& in, io::MeshModel& mm);

/// Lon/lat or stereographic view on the model's sphere as Mesh.PictureView says (the plane
/// as it is for a planar model), coloured as Mesh.PictureColour says (quality by default,
/// size, the size criterion or the depth at the nodes of `mm`, named in the legend), zoomed
/// to Mesh.PictureBox, the Mesh.PictureWorst worst triangles circled, Mesh.PictureWidth
/// pixels wide, Mesh.SaveAll as for the mesh files; into `po`. Returns "" or why not (a
/// value out of range, no size field for the criterion, no depth field).
std::string picture_options(Interpreter& in, const io::MeshModel& mm, io::PictureOptions& po);

}  // namespace sm::interp
