// The 2D pipeline (paper section 3.3): per face, in tag order, the steps over its
// FaceWork (face_work.h): boundary and plane (face_boundary), boundary mesh and sizing
// (face_boundary_mesh; the boundary layers before it, face_layer), the element budget (here), refinement (face_refine),
// smoothing and the quality pass (face_smooth), the quality floor (face_floor), output (face_output); a transfinite
// face is filled instead (face_transfinite); a filling Surface gets its plane from face_filling.
#include "mesh/mesh2d.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "base/elapsed.h"
#include "base/parallel.h"
#include "base/progress.h"
#include "base/release_memory.h"
#include "mesh/face_boundary.h"
#include "mesh/face_boundary_mesh.h"
#include "mesh/face_filling.h"
#include "mesh/face_floor.h"
#include "mesh/face_layer.h"
#include "mesh/face_output.h"
#include "mesh/face_periodic_copy.h"
#include "mesh/face_refine.h"
#include "mesh/face_sizing.h"
#include "mesh/face_smooth.h"
#include "mesh/face_transfinite.h"
#include "mesh/extrude_mesh.h"
#include "mesh/face_work.h"
#include "mesh/partition.h"

namespace sm {
namespace {

// From this many triangle slots on, a face gives the heap's free pages back to the system
// after each step (release_memory.h): each step's scratch arrays (per side or per vertex)
// are freed in the middle of the heap, where they would stay resident through the next
// steps (the full world at 10 km: 80 MiB resident over what is in use at the output).
// Smaller faces skip it: trimming walks the whole heap, a few milliseconds.
constexpr std::uint32_t kReleaseSlots = 65536;

void release_after_step(const FaceWork& f) {
  if (f.tri.num_slots() >= kReleaseSlots) release_free_memory();
}

// The estimated triangle count when something needs it (the element budget, the
// partitioning, the progress display); false when it is over Mesh.MaxElements.
bool check_budget(FaceWork& f, std::uint64_t& estimate) {
  // The estimate uses its own evaluator: the refiner's walk hints stay as without it. It
  // is counted in the size evaluations only when partitioning uses it.
  const bool partitioning = f.opt.partition.min_triangles > 0 && f.opt.algorithm != Mesh2dAlgorithm::MeshAdapt;
  if (!(partitioning || f.opt.progress || f.opt.max_elements > 0)) return true;
  std::atomic<std::uint64_t>* evaluations = partitioning ? &f.size_evaluations : nullptr;
  const int threads = resolve_thread_count(f.opt.threads);
  if (f.opt.size.extend_from_boundary == 0 && threads > 1) {
    // The size at a point depends on the point alone: the batches run on the threads, each
    // with an evaluator of its own, for the same estimate.
    const std::shared_ptr<const FaceSizing> sizing = f.sizing;
    const auto make_size = [sizing, evaluations]() -> PlaneSizeFn {
      auto sizes = std::make_shared<PlaneSizes>(*sizing, evaluations);
      return [sizes](std::span<const Vec2> p, std::span<double> h) { (*sizes)(p, h); };
    };
    estimate = estimate_triangles(f.tri, make_size, threads);
  } else {
    PlaneSizes estimate_sizes(*f.sizing, evaluations);
    const PlaneSizeFn estimate_at = [&estimate_sizes](std::span<const Vec2> p, std::span<double> h) {
      estimate_sizes(p, h);
    };
    estimate = estimate_triangles(f.tri, estimate_at);
  }
  if (f.opt.max_elements > 0 && static_cast<double>(estimate) > f.opt.max_elements) {
    f.fail(MeshProblem::None);
    f.res.error.kind = MeshErrorKind::LimitExceeded;
    f.res.error.count = static_cast<double>(estimate);
    f.res.error.limit = f.opt.max_elements;
    return false;
  }
  return true;
}

// The pipeline of one face: a transfinite one filled, any other through the steps in
// turn, each timed into its stage of Mesh2dStats.
bool run_face(FaceWork& f, const geo::ModelSurface& s) {
  if (is_layered_extrusion(f.model, s.tag)) return f.estimate_only || mesh_extruded_face(f, s);   // Extrude's Layers
  if (f.opt.constraints)
    if (const auto it = f.opt.constraints->surfaces.find(s.tag); it != f.opt.constraints->surfaces.end()) {
      if (f.estimate_only) return true;  // a grid: its count is the curves' product
      return mesh_transfinite_face(f, s, it->second);
    }
  f.plane.geom = s.geometry ? f.model.geometry(s.geometry) : nullptr;
  if (s.geometry && !f.plane.geom) return f.fail(MeshProblem::GeometryMissing, {s.geometry});
  auto t0 = std::chrono::steady_clock::now();
  if (!collect_boundary(f, s)) return false;
  if (s.filling && !s.geometry)
    choose_filling_plane(f, s);  // its boundary's plane or its patch's (face_filling.h)
  else if (!choose_plane(f))
    return false;
  if (!build_boundary_layers(f) || !triangulate_boundary(f)) return false;
  make_sizing(f);
  std::uint64_t estimate = 0;
  if (!check_budget(f, estimate)) return false;
  f.res.stats.seconds_boundary += seconds_since(t0);
  if (f.estimate_only) return true;
  if (f.opt.algorithm == Mesh2dAlgorithm::InitialOnly) {  // Gmsh's "initial mesh only"
    output_face(f);
    return true;
  }

  t0 = std::chrono::steady_clock::now();
  if (!refine_face(f, estimate)) return false;
  f.res.stats.size_evaluations += f.size_evaluations.exchange(0);
  f.res.stats.seconds_refine += seconds_since(t0);
  release_after_step(f);

  t0 = std::chrono::steady_clock::now();
  smooth_face(f);
  f.res.stats.seconds_smooth += seconds_since(t0);
  release_after_step(f);

  t0 = std::chrono::steady_clock::now();
  optimize_face(f);
  f.res.stats.seconds_optimize += seconds_since(t0);
  release_after_step(f);

  t0 = std::chrono::steady_clock::now();
  raise_face_floor(f);
  f.res.stats.seconds_floor += seconds_since(t0);
  release_after_step(f);

  t0 = std::chrono::steady_clock::now();
  output_face(f);
  f.res.stats.seconds_output += seconds_since(t0);
  return true;
}

// The periodic surfaces copied from `source`, then those copied from them (a chain; the
// interpreter refuses cycles, and each surface is copied once: at most copies.size() steps).
bool copy_periodic_faces(const geo::Model& model, ModelMesh& mesh, const Mesh2dOptions& opt, double bbox,
                         Mesh2dResult& res, std::vector<std::uint32_t>& local_of,
                         const std::map<int, PeriodicSurfaceSpec>& copies, int source, std::uint64_t& faces_done) {
  std::vector<int> sources{source};
  for (std::size_t next = 0; next < sources.size() && next <= copies.size(); ++next)
    for (const auto& [target, spec] : copies) {
      if (spec.source != sources[next] || !model.surface(target)) continue;
      FaceWork f(model, mesh, opt, bbox, res, local_of, target);
      if (!copy_periodic_face(f, spec)) return false;
      progress_update(opt.progress, ++faces_done);
      sources.push_back(target);
    }
  return true;
}

double model_bbox(const geo::Model& model, double given) {
  double bbox = given;
  if (!(bbox > 0)) bbox = model.bounding_box().diagonal();
  if (!(bbox > 0)) bbox = 1;
  return bbox;
}

}  // namespace

Mesh2dResult mesh_surfaces(const geo::Model& model, ModelMesh& mesh, const Mesh2dOptions& opt) {
  Mesh2dResult res;
  // What the script, the import and 1D freed stays resident under the mesher's arrays
  // otherwise (the full world at 10 km: 182 MiB resident, 112 MiB in use before 1D).
  release_free_memory();
  const double bbox = model_bbox(model, opt.bbox_diag);
  std::vector<std::uint32_t> local_of;
  progress_begin(opt.progress, "2D", model.surfaces().size());
  std::uint64_t faces_done = 0;
  const std::map<int, PeriodicSurfaceSpec> no_copies;
  const std::map<int, PeriodicSurfaceSpec>& copies = opt.constraints ? opt.constraints->periodic_surfaces : no_copies;
  for (const auto& [tag, s] : model.surfaces()) {
    if (copies.count(tag)) continue;   // a periodic surface: copied after its source
    Mesh2dOptions own;  // a face with an algorithm of its own: the options with it
    const auto algo = opt.surface_algorithm.find(tag);
    if (algo != opt.surface_algorithm.end()) {
      own = opt;
      own.algorithm = algo->second;
    }
    FaceWork f(model, mesh, algo != opt.surface_algorithm.end() ? own : opt, bbox, res, local_of, s.tag);
    if (!run_face(f, s) || !copy_periodic_faces(model, mesh, opt, bbox, res, local_of, copies, tag, faces_done)) {
      progress_end(opt.progress);
      return res;
    }
    progress_update(opt.progress, ++faces_done);
  }
  progress_end(opt.progress);
  // The last face's store, freed by its output, under the statistics' arrays otherwise.
  release_free_memory();
  mesh.dim = std::max(mesh.dim, 2);
  return res;
}

Mesh2dResult check_face_budgets(const geo::Model& model, const ModelMesh& coarse, const Mesh2dOptions& base) {
  Mesh2dResult res;
  if (!(base.max_elements > 0)) return res;
  Mesh2dOptions opt = base;
  opt.progress = nullptr;
  ModelMesh mesh = coarse;
  const double bbox = model_bbox(model, opt.bbox_diag);
  std::vector<std::uint32_t> local_of;
  for (const auto& [tag, s] : model.surfaces()) {
    Mesh2dResult face;
    FaceWork f(model, mesh, opt, bbox, face, local_of, s.tag);
    f.estimate_only = true;
    if (!run_face(f, s) && face.error.kind == MeshErrorKind::LimitExceeded) {
      res.error = face.error;
      return res;
    }
  }
  return res;
}

std::vector<StageTime> stage_times(const Mesh2dStats& s) {
  return {
      {"2D boundary", s.seconds_boundary}, {"2D refine", s.seconds_refine},       {"2D smooth", s.seconds_smooth},
      {"2D optimise", s.seconds_optimize}, {"2D quality floor", s.seconds_floor}, {"2D output", s.seconds_output},
  };
}

}  // namespace sm
