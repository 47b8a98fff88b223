// Step 5 of a face (face_work.h): refinement by Mesh.Algorithm.
#pragma once

#include <cstdint>

#include "mesh/face_work.h"

namespace sm {

/// Refines f.tri to f.sizing: del2d or front2d (in parts on threads, partition.h, when
/// `estimate`, the face's estimated triangle count, reaches opt.partition.min_triangles)
/// or meshadapt (serial; it smooths in each round: f.smoothed). Counts into f.res.stats;
/// false (f.res.error) when the refiner fails.
bool refine_face(FaceWork& f, std::uint64_t estimate);

}  // namespace sm
