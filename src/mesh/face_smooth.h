// Step 6 of a face (face_work.h): Laplacian smoothing and the quality pass.
#pragma once

#include "mesh/face_work.h"

namespace sm {

/// Mesh.Smoothing passes of smooth_laplacian over f.tri (none after meshadapt, which
/// smoothed in its rounds); a face with embedded points pins every input vertex.
void smooth_face(FaceWork& f);

/// The quality pass (optimize_quality, Mesh.QualityPass) after smoothing; del2d gets its
/// cheaper settings.
void optimize_face(FaceWork& f);

}  // namespace sm
