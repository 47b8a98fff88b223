// A picture of the mesh as SVG, for people to look at before they trust a
// mesh: the Scene of io/picture.h (triangles optionally coloured by quality or
// a node field, boundary curves highlighted) as XML.
#pragma once

#include <string>

#include "io/mesh_model.h"
#include "io/picture.h"

namespace sm::io {

/// The SVG document: one <polygon> per scene triangle (two where a triangle
/// crosses the dateline in the lon/lat view), one <polyline> per chain of curve edges.
std::string svg_to_string(const Scene& scene);
std::string svg_to_string(const MeshModel& mesh, const PictureOptions& opt);
/// Writes atomically; *error is the reason on failure, without the path (see msh_writer.h).
bool save_svg(const MeshModel& mesh, const PictureOptions& opt, const std::string& path, std::string* error);

}  // namespace sm::io
