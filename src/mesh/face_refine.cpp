// Step 5 of a face: del2d / front2d refinement with the size converted to the plane (h /
// lambda on a PolarSphere; large faces in parts on threads, partition.h), or meshadapt
// (face_refine.h).
#include "mesh/face_refine.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <span>

#include "base/parallel.h"
#include "base/progress.h"
#include "mesh/face_sizing.h"
#include "mesh/frontal.h"
#include "mesh/meshadapt.h"
#include "mesh/modify/smooth.h"
#include "mesh/partition.h"
#include "mesh/refine.h"

namespace sm {
namespace {

// del2d's bound on circumradius / size. refine.h's 1/sqrt2 leaves edges short (square
// with holes, lc 0.03: median edge/size 0.92, 94.0% in [0.7, 1.4]); 0.76 centres them
// (0.98, 96.9%) but on the world ocean gives fewer well-shaped triangles than Gmsh (74.6%
// rho > 0.9 against 76.5%); 0.73 keeps both: square 95.6% in range, world 76.2% rho > 0.9
// and 95.4% in range (Gmsh: 91.5%).
constexpr double kDel2dRadiusLimit = 0.73;

// A face refined in one piece gets its own progress stage from this estimated size on
// (smaller ones refine in well under a tenth of a second).
constexpr std::uint64_t kNestedProgressTriangles = 65536;

// RefineOptions::vertex_size_scale of the face: 1 / lambda on a sphere or a filling
// patch, null on a plane.
PlaneSizeFn plane_scale(const FaceWork& f) {
  if (!f.plane.scaled()) return nullptr;
  const std::shared_ptr<const FaceSizing> sizing = f.sizing;
  return [sizing](std::span<const Vec2> p, std::span<double> h) {
    for (std::size_t i = 0; i < p.size(); ++i) h[i] = 1 / sizing->plane.lambda(p[i]);
  };
}

// del2d or front2d on the face: in one piece, or in parts (partition.h) when the estimated
// triangle count reaches opt.partition.min_triangles. The part count depends on the
// estimate only, so the mesh is the same for every thread count.
bool refine_in_plane(FaceWork& f, const std::function<void(std::span<const Vec2>, std::span<double>)>& size_at,
                     std::uint64_t estimate) {
  RefineOptions ro;
  ro.max_vertices = f.opt.max_vertices_per_face;
  ro.size_at = size_at;
  // The boundary sizes extended into the face size a triangle by its vertices, as Gmsh's
  // refiners do (RefineOptions::vertex_size_at); the rest of the size at its circumcentre.
  std::shared_ptr<PlaneSizes> without_ext, ext_only;
  if (f.opt.size.extend_from_boundary != 0) {
    without_ext = std::make_shared<PlaneSizes>(*f.sizing, &f.size_evaluations, PlaneSizes::Part::WithoutExtension);
    ext_only = std::make_shared<PlaneSizes>(*f.sizing, &f.size_evaluations, PlaneSizes::Part::ExtensionOnly);
    ro.size_at = [without_ext](std::span<const Vec2> p, std::span<double> h) { (*without_ext)(p, h); };
    ro.vertex_size_at = [ext_only](std::span<const Vec2> p, std::span<double> h) { ext_only->on_surface(p, h); };
    ro.vertex_size_scale = plane_scale(f);
  }
  const bool frontal = f.opt.algorithm == Mesh2dAlgorithm::Frontal;
  ro.gmsh_rejection = frontal && f.opt.gmsh_rejection;
  if (f.opt.radius_limit > 0)
    ro.radius_limit = f.opt.radius_limit;
  else if (!frontal)
    ro.radius_limit = kDel2dRadiusLimit;
  const bool partitioning = f.opt.partition.min_triangles > 0;
  if (partitioning && estimate >= f.opt.partition.min_triangles) {
    ro.size_at = nullptr;
    ro.vertex_size_at = nullptr;
    // Each part carries the extension by its vertices too, with functions of its own.
    std::function<void(RefineOptions&)> part_sizes;
    if (f.opt.size.extend_from_boundary != 0)
      part_sizes = [&f](RefineOptions& o) {
        auto w = std::make_shared<PlaneSizes>(*f.sizing, &f.size_evaluations, PlaneSizes::Part::WithoutExtension);
        auto x = std::make_shared<PlaneSizes>(*f.sizing, &f.size_evaluations, PlaneSizes::Part::ExtensionOnly);
        o.size_at = [w](std::span<const Vec2> p, std::span<double> h) { (*w)(p, h); };
        o.vertex_size_at = [x](std::span<const Vec2> p, std::span<double> h) { x->on_surface(p, h); };
        o.vertex_size_scale = plane_scale(f);
      };
    const auto make_size = [&f]() -> PlaneSizeFn {
      auto sizes = std::make_shared<PlaneSizes>(*f.sizing, &f.size_evaluations);
      return [sizes](std::span<const Vec2> p, std::span<double> h) { (*sizes)(p, h); };
    };
    // "2D refine", nested in "2D", one unit per part: a large face is one unit of "2D"
    // that would otherwise show nothing for seconds. Reported from this thread only.
    bool nested = false;
    const auto on_parts = [&f, &nested](std::uint32_t done, std::uint32_t parts) {
      if (!f.opt.progress) return;
      if (!nested) progress_begin(f.opt.progress, "2D refine", parts), nested = true;
      progress_update(f.opt.progress, done);
    };
    // Without the extension the size at a point depends on the point alone, so the serial
    // steps may size their large batches on the threads (PartitionOptions::sizes_by_point).
    PartitionOptions po = f.opt.partition;
    po.sizes_by_point = f.opt.size.extend_from_boundary == 0;
    const PartitionResult pr = refine_partitioned(f.tri, ro, frontal ? PartRefiner::Frontal : PartRefiner::Del2d,
                                                  make_size, po, resolve_thread_count(f.opt.threads), on_parts,
                                                  part_sizes);
    if (nested) progress_end(f.opt.progress);
    f.res.stats.inserted += pr.stats.refine.inserted;
    f.res.stats.rejected += pr.stats.refine.rejected;
    f.res.stats.parts += pr.stats.parts;
    f.res.stats.estimated_triangles += pr.stats.estimate;
    ++f.res.stats.partitioned_faces;
    if (!pr.ok()) return f.fail_because(MeshProblem::RefinementFailed, pr.error);
    // Parts are Delaunay inside; smoothing ends with flips that make the seams so too.
    if (f.opt.smoothing <= 0) make_delaunay(f.tri, resolve_thread_count(f.opt.threads));
    return true;
  }
  // A large face in one piece: "2D refine" nested in "2D" in estimated triangles, told
  // by the refiner every 64k insertions (done is capped at the estimate, which it may pass).
  const bool nested = f.opt.progress && estimate >= kNestedProgressTriangles;
  if (nested) {
    progress_begin(f.opt.progress, "2D refine", estimate);
    ro.on_progress = [&f, estimate](std::uint64_t triangles) {
      progress_update(f.opt.progress, std::min(triangles, estimate));
    };
  }
  RefineResult rf;
  if (frontal)
    rf = refine_front2d(f.tri, ro);
  else
    rf = refine_del2d(f.tri, ro);
  if (nested) {
    if (rf.ok()) progress_update(f.opt.progress, estimate);
    progress_end(f.opt.progress);
  }
  f.res.stats.inserted += rf.stats.inserted;
  f.res.stats.rejected += rf.stats.rejected;
  if (!rf.ok()) return f.fail_because(MeshProblem::RefinementFailed, rf.error);
  return true;
}

}  // namespace

bool refine_face(FaceWork& f, std::uint64_t estimate) {
  PlaneSizes sizes(*f.sizing, &f.size_evaluations);
  const auto size_at = [&sizes](std::span<const Vec2> p, std::span<double> h) { sizes(p, h); };
  if (f.opt.algorithm != Mesh2dAlgorithm::MeshAdapt) return refine_in_plane(f, size_at, estimate);
  // Meshadapt is serial: its rounds of split/collapse/swap act on the whole face.
  MeshAdaptOptions mo;
  mo.size_at = size_at;
  mo.smoothing_passes = std::max(0, f.opt.smoothing);
  mo.max_vertices = f.opt.max_vertices_per_face;
  const MeshAdaptResult ma = mesh_adapt(f.tri, mo);
  if (!ma.ok()) return f.fail_because(MeshProblem::MeshAdaptFailed, ma.error);
  f.res.stats.inserted += ma.stats.splits;
  f.smoothed = true;
  return true;
}

}  // namespace sm
