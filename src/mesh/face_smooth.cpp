// Step 6 of a face: smoothing, then the quality pass (face_smooth.h).
#include "mesh/face_smooth.h"

#include "base/parallel.h"
#include "mesh/modify/optimize.h"
#include "mesh/modify/smooth.h"

namespace sm {

void smooth_face(FaceWork& f) {
  if (f.opt.smoothing <= 0 || f.smoothed) return;
  // smooth_laplacian keeps vertices of constrained edges in place; an isolated embedded
  // point is on none and would move: such faces pin every input vertex.
  const std::uint32_t pinned = f.emb_points.empty() ? 0 : f.fixed_count;
  smooth_laplacian(f.tri, f.opt.smoothing, resolve_thread_count(f.opt.threads), pinned);
}

void optimize_face(FaceWork& f) {
  if (f.opt.smoothing <= 0 || !f.opt.quality_pass) return;
  OptimizeOptions oo;
  if (f.opt.algorithm == Mesh2dAlgorithm::Del2d || f.opt.algorithm == Mesh2dAlgorithm::Automatic) {
    // del2d's many triangles just under 0.9 would cost ~4x the refinement to lift
    // (square: 87% -> 99% rho > 0.9); work on the bad ones only (~20% of refinement).
    oo.threshold = 0.75;
    oo.sacrifice_below = 0.7;
    oo.max_share_loss = 1e-4;
  }
  oo.threads = resolve_thread_count(f.opt.threads);
  optimize_quality(f.tri, f.fixed_count, oo);
}

}  // namespace sm
