// A picture of the mesh as PNG: the Scene of io/picture.h rasterised with cairo
// (antialiased), for docs, reports and viewers that do not take SVG.
#pragma once

#include <string>

#include "io/mesh_model.h"
#include "io/picture.h"

namespace sm::io {

/// The PNG file's bytes: an RGB image of scene.width x scene.height (rounded) pixels.
/// Empty with `error` set when cairo fails (out of memory, say).
std::string png_to_string(const Scene& scene, std::string* error);
/// Writes atomically; *error is the reason on failure, without the path (see msh_writer.h).
bool save_png(const MeshModel& mesh, const PictureOptions& opt, const std::string& path, std::string* error);

}  // namespace sm::io
