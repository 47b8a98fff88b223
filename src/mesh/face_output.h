// Step 8 of a face (face_work.h): its elements in the model mesh.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/face_work.h"
#include "mesh/model_mesh.h"

namespace sm {

/// The interior nodes of f.tri to 3D (their (u,v) on a geometry), its triangles oriented
/// (paired into quadrangles by recombine.h where the surface is recombined), the
/// surface's mesh stored and its target size kept in f.res.target_sizes. f.tri is
/// emptied (freed before the nodes are made: the output is the face's last step).
void output_face(FaceWork& f);

/// Appends elements to `out`, their corners mapped by `node` (local -> global node) and
/// reversed when `flip` (the plane's counter-clockwise is not the outward normal).
void append_elements(SurfaceMesh& out, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                     const std::vector<std::array<std::uint32_t, 4>>& quads, bool flip,
                     std::span<const std::uint32_t> node);

/// `out` counted into f.res.stats and stored as surface f.tag of f.mesh.
void store_surface(FaceWork& f, SurfaceMesh out);

}  // namespace sm
