// Mesh commands: `Mesh 1;` runs the 1D mesher (mesh/mesh1d) on the model with the
// script's Mesh.* options and Background Field, `Mesh 2;` then meshes the faces
// (mesh/mesh2d, Mesh.Algorithm 1, 2, 5, 6 or 8, with the structured constraints of
// KernelState::constraints) and prints the statistics, `Save "f";`
// writes the current mesh atomically in a format of io/output_format.h, `PartitionMesh N;`
// partitions it (interp/kernel/partition_export.h), and the command line's -1 / -2 mesh
// and write. The other mesh commands and post-processing
// statements are reported as not supported.
#include "interp/kernel/mesh_commands.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <new>

#include <fmt/format.h>

#include "base/output_file.h"
#include "interp/kernel/dispatch.h"
#include "mesh/discrete_mesh.h"
#include "mesh/periodic_curve.h"
#include "interp/kernel/field_context.h"
#include "interp/kernel/field_eval.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/kernel/mesh_note_words.h"
#include "interp/kernel/mesh_error_words.h"
#include "interp/kernel/node_data_export.h"
#include "interp/kernel/ocean_grid_export.h"
#include "interp/kernel/output_options.h"
#include "interp/kernel/partition_export.h"
#include "interp/kernel/quality_floor_option.h"
#include "interp/kernel/size_policy_from_options.h"
#include "interp/interpreter.h"
#include "interp/provenance.h"
#include "interp/progress_sink.h"
#include "io/from_model_mesh.h"
#include "io/output_format.h"
#include "mesh/compound_surface.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"
#include "mesh/mesh2d_algorithms.h"
#include "mesh/mesh_stats.h"
#include "mesh/time_step.h"
#include "mesh/time_step_repair.h"
#include "field/time_step_floor.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

Mesh1dOptions mesh1d_options(Interpreter& in, const field::SizeField* background) {
  const Options& o = in.options();
  Mesh1dOptions opt;
  opt.size = size_policy_from_options(o);
  opt.background = background;
  opt.bbox_diag = model_bbox_diag(in.kernel().model);
  opt.min_curve_nodes = static_cast<int>(o.number("Mesh.MinimumCurveNodes"));
  opt.min_circle_nodes = static_cast<int>(o.number("Mesh.MinimumCircleNodes"));
  opt.smooth_ratio = o.number("Mesh.SmoothRatio");
  // Threads over curves: Mesh.MaxNumThreads1D, else General.NumThreads (0: the
  // hardware's); the 1D mesh is the same for any count.
  const int threads_1d = static_cast<int>(o.number("Mesh.MaxNumThreads1D"));
  opt.threads = threads_1d > 0 ? threads_1d : static_cast<int>(o.number("General.NumThreads"));
  opt.progress = progress_sink(in);
  return opt;
}

template <class... Args>
std::pair<Diag, std::string> worded_mesh(std::type_identity_t<DiagFormat<Args...>> kind, const Args&... args) {
  return {kind.kind(), format_diag<Args...>(kind, args...)};
}

// A crossing of the 1D mesh (one curve, or two) or two curves' nodes at one place, with the
// curves and the place: lon/lat on a sphere, else the model's x, y, z.
std::pair<Diag, std::string> worded_crossing(const MeshError& e) {
  const int a = e.tag(0), b = e.tag(1);
  const bool itself = b == 0;
  const double lon = e.where.lon, lat = e.where.lat, x = e.xyz.x, y = e.xyz.y, z = e.xyz.z;
  if (e.kind == MeshErrorKind::DuplicatePoint) {
    const int second = itself ? a : b;
    if (e.has_lonlat) return worded_mesh(Diag::MeshCurvesShareNodePlace, a, second, lon, lat);
    return worded_mesh(Diag::MeshCurvesShareNodePlaceXyz, a, second, x, y, z);
  }
  if (itself && e.has_lonlat) return worded_mesh(Diag::MeshCurveCrossesItself, a, lon, lat);
  if (itself) return worded_mesh(Diag::MeshCurveCrossesItselfXyz, a, x, y, z);
  if (e.has_lonlat) return worded_mesh(Diag::MeshCurvesCross, a, b, lon, lat);
  return worded_mesh(Diag::MeshCurvesCrossXyz, a, b, x, y, z);
}

// Mesh.MinTimeStep's size floor is this times dt sqrt(g H): a frontal mesh's edges run
// from about 0.7 to 1.4 of the size (docs/kernel.md), so the shortest stays near dt sqrt(g H).
constexpr double kMinStepSizeFactor = 1.5;
// The places under Mesh.MinTimeStep listed after meshing, worst first (the count says the rest).
constexpr std::size_t kMaxStepUnmetReported = 10;

// A 1D mesher error's kind and message: a node count over its limit says which limit, as
// the user can change it (Mesh.MaxElements, or the cap of nodes on one curve).
std::pair<Diag, std::string> worded_1d(const MeshError& e) {
  if (e.kind == MeshErrorKind::Intersection || e.kind == MeshErrorKind::DuplicatePoint) return worded_crossing(e);
  if (e.kind != MeshErrorKind::LimitExceeded) return worded_mesh_problem(e);
  const bool cap = e.limit >= kMaxCurveNodes;
  if (e.all_curves && cap)
    return {Diag::LimitAllCurvesCap,
            format_diag<double, int, double>(Diag::LimitAllCurvesCap, e.count, e.tag(0), e.limit)};
  if (e.all_curves)
    return {Diag::LimitAllCurvesBudget,
            format_diag<double, int, double>(Diag::LimitAllCurvesBudget, e.count, e.tag(0), e.limit)};
  if (cap)
    return {Diag::LimitCurveNodesCap,
            format_diag<int, double, double>(Diag::LimitCurveNodesCap, e.tag(0), e.count, e.limit)};
  return {Diag::LimitCurveNodesBudget,
          format_diag<int, double, double>(Diag::LimitCurveNodesBudget, e.tag(0), e.count, e.limit)};
}

// A meshing failure on its way to a diagnostic (kind, message, notes at the
// statements that created the entities involved, the failing entity's first).
struct MeshFailure {
  Diag kind = Diag::MeshNoProblemNamed;
  std::string message;
  std::vector<DiagNote> notes;
  bool failed() const { return !message.empty(); }
};

// A 2D mesher error's kind and message, a compound's union named by its surfaces.
MeshFailure failure_of(const KernelState& k, const MeshError& e, const CompoundSurfacePlan& compounds) {
  if (e.kind == MeshErrorKind::LimitExceeded)
    return {Diag::LimitSurfaceTriangles,
            format_diag<int, double, double>(Diag::LimitSurfaceTriangles, e.tag(0), e.count, e.limit),
            provenance_notes(k, e)};
  auto [kind, message] = worded_mesh_problem(e);
  name_compound_unions(compounds, message);
  return {kind, std::move(message), provenance_notes(k, e)};
}

// `t` summed into the entry of its name in `times` (appended when there is none).
void add_stage_time(std::vector<StageTime>& times, const StageTime& t) {
  for (StageTime& have : times)
    if (have.name == t.name) {
      have.seconds += t.seconds;
      return;
    }
  times.push_back(t);
}

// Publishes the statistics as read-only options and prints the summary.
void publish_stats(Interpreter& in, const ModelMesh& mesh, const MeshStats& st) {
  Options& o = in.options();
  // The nodes of the 2D elements, as the summary and every written file count them
  // (io/from_model_mesh.h): not the left-out islands' curves nor construction points.
  o.set_number("Mesh.NbNodes", static_cast<double>(st.nodes), /*internal=*/true);
  o.set_number("Mesh.NbTriangles", static_cast<double>(st.triangles), true);
  o.set_number("Mesh.NbQuadrangles", static_cast<double>(st.quads), true);
  o.set_number("Mesh.StatsRhoMin", st.min_rho, true);
  o.set_number("Mesh.StatsRhoMean", st.mean_rho, true);
  o.set_number("Mesh.StatsRhoAbove09", st.share_rho_09, true);
  o.set_number("Mesh.StatsEdgeRatioMedian", st.len_median, true);
  o.set_number("Mesh.StatsEdgeInRange", st.share_len_07_14, true);
  o.set_number("Mesh.StatsTimeStep", st.time_step.valid ? st.time_step.dt : 0, true);
  o.set_number("Mesh.StatsDepthClamped", st.has_depth_clamp ? static_cast<double>(st.depth_clamp.clamped) : 0, true);
  in.kernel().mesh_stats = st;
  in.kernel().has_mesh_stats = true;
  in.kernel().has_curve_stats = false;
  if (o.number("General.Verbosity") >= 4) {
    std::fflush(stdout);   // after the Printf output before it when both share a pipe
    std::fputs(format_stats(st).c_str(), stderr);
    std::fflush(stderr);
  }
}

// The Courant time step of `mesh` with node depths `h` (Mesh.DepthField's): edges
// on the model's sphere when it has one (lengths in the model's units, metres for
// earth.geo), depths raised to Mesh.TimeStepMinDepth.
TimeStepOptions time_step_options(Interpreter& in) {
  TimeStepOptions opt;
  opt.min_depth = in.options().number("Mesh.TimeStepMinDepth");
  for (const auto& [tag, g] : in.kernel().model.geometries()) {
    opt.centre = g.centre();
    opt.radius = g.radius();
    break;
  }
  return opt;
}

std::vector<double> node_depths(const ModelMesh& mesh, const field::SizeField& depth) {
  std::vector<Vec3> xyz(mesh.nodes.size());
  for (std::size_t i = 0; i < xyz.size(); ++i) xyz[i] = mesh.nodes[i].xyz;
  std::vector<double> h(xyz.size());
  depth.eval(xyz, h);
  return h;
}

// Mesh.MinTimeStep after meshing: the nodes behind too short steps removed
// (mesh/time_step_repair.h), each a warning with its place; then every place still under
// the step, worst first (a few: the count says how many), as warnings too.
void enforce_min_time_step(Interpreter& in, ModelMesh& mesh, const field::SizeField& depth, double min_step,
                           SourceRange where) {
  const std::vector<double> h = node_depths(mesh, depth);
  const TimeStepOptions opt = time_step_options(in);
  const StepRepairResult r = repair_short_steps(mesh, h, min_step, opt);
  for (const StepRemoval& rm : r.removed) {
    double lon = 0, lat = 0;
    time_step_lonlat(rm.where, opt, lon, lat);
    in.diags().report(where, Diag::MeshStepNodeRemoved, rm.surface, lon, lat, rm.edge, rm.step);
  }
  const std::vector<double> steps = triangle_time_steps(mesh, h, opt);
  std::vector<std::pair<double, std::size_t>> under;
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (steps[i] < min_step) under.push_back({steps[i], i});
  std::sort(under.begin(), under.end());
  std::vector<Vec3> centroid;
  for (const auto& [tag, sf] : mesh.surfaces)
    for (const auto& t : sf.triangles)
      if (centroid.size() < steps.size())
        centroid.push_back((mesh.nodes[t[0]].xyz + mesh.nodes[t[1]].xyz + mesh.nodes[t[2]].xyz) / 3.0);
  for (std::size_t i = 0; i < under.size() && i < kMaxStepUnmetReported; ++i) {
    double lon = 0, lat = 0;
    time_step_lonlat(centroid[under[i].second], opt, lon, lat);
    if (under.size() > kMaxStepUnmetReported)
      in.diags().report(where, Diag::MeshStepUnmetWorst, min_step, lon, lat, under[i].first, under.size());
    else
      in.diags().report(where, Diag::MeshStepUnmet, min_step, lon, lat, under[i].first, under.size());
  }
}

TimeStep time_step_of(Interpreter& in, const ModelMesh& mesh, const std::vector<double>& h) {
  return courant_time_step(mesh, h, time_step_options(in));
}

// One line on what the depth field's MinDepth did to the nodes, at the field's definition
// (a model run on depths raised without a word is not the one its author meant).
void report_depth_clamp(Interpreter& in, const field::DepthClampReport& c) {
  const KernelState& k = in.kernel();
  const int id = static_cast<int>(in.options().number("Mesh.DepthField"));
  const auto def = k.field_defined_at.find(id);
  if (def == k.field_defined_at.end()) return;
  const double share = c.points ? 100.0 * static_cast<double>(c.clamped) / static_cast<double>(c.points) : 0.0;
  if (c.has_worst)
    in.diags().report(def->second, Diag::DepthMinClampWorst, id, c.min_depth, c.clamped, c.points, share, c.dry, c.lon,
                      c.lat, c.grid_depth, c.value);
  else
    in.diags().report(def->second, Diag::DepthMinClamp, id, c.min_depth, c.clamped, c.points, share, c.dry);
}

// The notes pointing at where `option` was set, if a statement set it.
std::vector<DiagNote> set_here(const KernelState& k, const std::string& option) {
  std::vector<DiagNote> notes;
  if (const auto it = k.option_set_at.find(option); it != k.option_set_at.end())
    notes.push_back({it->second, option + " was set here"});
  return notes;
}

// The 2D mesher's options from Mesh.*: the algorithm, sizes, passes and threads.
MeshFailure mesh2d_options(Interpreter& in, const field::SizeField* background, Mesh2dOptions& opt2) {
  KernelState& k = in.kernel();
  const int algo = static_cast<int>(in.options().number("Mesh.Algorithm"));
  // A row of mesh/mesh2d_algorithms.h; the others are refused by their number.
  const Mesh2dAlgorithmRow* row = mesh2d_algorithm_numbered(algo);
  if (!row) {
    MeshFailure f{Diag::MeshAlgorithmUnavailable,
                  format_diag(Diag::MeshAlgorithmUnavailable, algo, mesh2d_algorithm_numbers()), {}};
    if (const auto it = k.option_set_at.find("Mesh.Algorithm"); it != k.option_set_at.end())
      f.notes.push_back({it->second, "Mesh.Algorithm was set here"});
    return f;
  }
  opt2.algorithm = row->algorithm;
  opt2.size = size_policy_from_options(in.options());
  opt2.background = background;
  opt2.bbox_diag = model_bbox_diag(k.model);
  opt2.smoothing = static_cast<int>(in.options().number("Mesh.Smoothing"));
  opt2.quality_pass = in.options().number("Mesh.QualityPass") != 0;
  opt2.quality_floor = quality_floor_in_effect(in);
  opt2.gmsh_rejection = gmsh_rejection_in_effect(k);
  opt2.max_elements = in.options().number("Mesh.MaxElements");
  // Threads for faces refined in parts: Mesh.MaxNumThreads2D, else General.NumThreads (0:
  // the hardware's). The mesh is the same for any count; meshadapt stays serial.
  const int threads_2d = static_cast<int>(in.options().number("Mesh.MaxNumThreads2D"));
  opt2.threads = threads_2d > 0 ? threads_2d : static_cast<int>(in.options().number("General.NumThreads"));
  return {};
}

// The depth field named by Mesh.DepthField, built now so that one that names no field or
// cannot be built is reported before the meshing is paid for (it is read only when a
// fort.14 / hgrid.gr3 is written, after meshing); null when none is set.
MeshFailure depth_field_for_mesh(Interpreter& in, field::FieldPtr& depth) {
  KernelState& k = in.kernel();
  const double depth_field = in.options().number("Mesh.DepthField");
  if (!(depth_field > 0)) return {};
  if (!k.field_defined_at.count(static_cast<int>(depth_field))) {
    MeshFailure f{Diag::DepthFieldNamesNoField, format_diag(Diag::DepthFieldNamesNoField, depth_field), {}};
    if (const auto it = k.option_set_at.find("Mesh.DepthField"); it != k.option_set_at.end())
      f.notes.push_back({it->second, "Mesh.DepthField was set here"});
    return f;
  }
  const auto it = k.option_set_at.find("Mesh.DepthField");
  const int id = static_cast<int>(depth_field);
  depth = built_fields(in, id, it != k.option_set_at.end() ? it->second : SourceRange{}).shared(id);
  if (OptionRefusal r = check_depth_sampling(in, *depth); !r.empty())
    return {r.kind, std::move(r.message), set_here(k, "Mesh.DepthSampling")};
  return {};
}

// The structured constraints with the Mesh.* options that complete them, and each
// surface's own algorithm (MeshAlgorithm Surface).
MeshFailure structured_constraints(Interpreter& in, int dim, Mesh2dOptions& opt2) {
  KernelState& k = in.kernel();
  MeshConstraints& constraints = k.constraints;
  constraints.recombine_all = in.options().number("Mesh.RecombineAll") != 0;
  const int recombination = static_cast<int>(in.options().number("Mesh.RecombinationAlgorithm"));
  const bool recombining = constraints.recombine_all || !constraints.recombine.empty();
  if (dim >= 2 && recombining && recombination > 1)
    return {Diag::RecombinationFullQuad, format_diag(Diag::RecombinationFullQuad, recombination),
            set_here(k, "Mesh.RecombinationAlgorithm")};
  constraints.algorithm = recombination == 0 ? RecombineAlgorithm::Simple : RecombineAlgorithm::Matching;
  opt2.constraints = &constraints;
  for (const auto& [surface, algo] : constraints.surface_algorithm) {
    const Mesh2dAlgorithmRow* row = mesh2d_algorithm_numbered(algo);
    if (!row)
      return MeshFailure{
          Diag::MeshSurfaceAlgorithmUnavailable,
          format_diag(Diag::MeshSurfaceAlgorithmUnavailable, surface, algo, mesh2d_algorithm_numbers()),
          {}};
    opt2.surface_algorithm[surface] = row->algorithm;
  }
  return {};
}

// The boundary-layer fields, built here so that bad options and missing curves are
// reported at their statements before anything is meshed.
std::vector<field::BoundaryLayerParams> boundary_layers_of(Interpreter& in) {
  KernelState& k = in.kernel();
  std::vector<field::BoundaryLayerParams> layers;
  for (const auto& [fid, at] : k.boundary_layer_fields) {
    if (!k.fields.contains(fid))
      in.fail(at, Diag::MissingBoundaryLayerField, fid);
    const std::string kind = k.fields.options(fid).kind().name;
    if (kind != "BoundaryLayer")
      in.fail(at, Diag::BoundaryLayerFieldWrongKind, fid, kind);
    (void)built_fields(in, fid, at);
    try {
      layers.push_back(field::boundary_layer_params(k.fields.options(fid), fid));
    } catch (const field::FieldError& e) {
      fail_field_error(in, e, at);
    }
  }
  return layers;
}

// -1's end: the node count and the summary of the curves' edges, as -2 prints the 2D
// statistics (edges along the model's sphere when it has one: metres with earth.geo, as
// the time step measures them).
MeshFailure finish_1d(Interpreter& in, std::shared_ptr<ModelMesh> mesh) {
  KernelState& k = in.kernel();
  if (in.options().number("Mesh.NbPartitions") > 0)
    return {Diag::PartitionsNeed2dMesh,
            format_diag(Diag::PartitionsNeed2dMesh, in.options().number("Mesh.NbPartitions")),
            set_here(k, "Mesh.NbPartitions")};
  in.options().set_number("Mesh.NbNodes", static_cast<double>(mesh->nodes.size()), /*internal=*/true);
  Vec3 centre{};
  double radius = 0;
  for (const auto& [tag, g] : k.model.geometries()) {
    centre = g.centre();
    radius = g.radius();
    break;
  }
  k.curve_stats = curve_stats(*mesh, centre, radius);
  k.has_curve_stats = true;
  k.has_mesh_stats = false;
  if (in.options().number("General.Verbosity") >= 4) {
    std::fflush(stdout);
    std::fputs(format_curve_stats(k.curve_stats).c_str(), stderr);
    std::fflush(stderr);
  }
  k.mesh = std::move(mesh);
  return {};
}

// The worst triangle's place in longitude/latitude when its surface is on a sphere.
void locate_worst_triangle(const geo::Model& model, MeshStats& st) {
  const geo::ModelSurface* ws = st.min_rho_surface ? model.surface(st.min_rho_surface) : nullptr;
  const geo::SurfaceGeometry* g = ws && ws->geometry ? model.geometry(ws->geometry) : nullptr;
  if (!g) return;
  geo::LonLat ll;
  if (g->polar()) {
    ll = g->polar()->to_lonlat(st.min_rho_at);
  } else {
    const Vec2 uv = g->param(st.min_rho_at);
    ll = {uv.x * geo::kRadToDeg, uv.y * geo::kRadToDeg};
  }
  st.has_min_rho_lonlat = true;
  st.min_rho_lon = ll.lon, st.min_rho_lat = ll.lat;
}

// The depths the ocean grids get at the nodes of the 2D elements (those the written files
// hold; Mesh.DepthSampling included), the time step they give, and what MinDepth did to them.
MeshFailure depth_and_time_step(Interpreter& in, const ModelMesh& mesh, MeshStats& st) {
  constexpr std::uint32_t kUnused = 0xFFFFFFFFu;
  std::vector<std::uint32_t> local(mesh.nodes.size(), kUnused);
  std::vector<Vec3> xyz;
  auto use = [&](std::uint32_t v) {
    if (local[v] == kUnused) {
      local[v] = static_cast<std::uint32_t>(xyz.size());
      xyz.push_back(mesh.nodes[v].xyz);
    }
    return local[v];
  };
  std::vector<std::array<std::uint32_t, 2>> edges;
  const bool sampled = in.options().number("Mesh.DepthSampling") == 1;
  auto add_element = [&](const std::uint32_t* corners, std::size_t n) {
    for (std::size_t c = 0; c < n; ++c) {
      const std::uint32_t a = use(corners[c]), b = use(corners[(c + 1) % n]);
      if (sampled) edges.push_back({a, b});
    }
  };
  for (const auto& [tag, surf] : mesh.surfaces) {
    for (const auto& t : surf.triangles) add_element(t.data(), 3);
    for (const auto& q : surf.quads) add_element(q.data(), 4);
  }
  std::vector<double> h;
  std::optional<field::DepthClampReport> clamp;
  if (OptionRefusal r = depth_at(in, xyz, edges, h, &clamp); !r.empty())
    return {r.kind, std::move(r.message), set_here(in.kernel(), "Mesh.DepthField")};
  std::vector<double> node_h(mesh.nodes.size(), 0.0);   // nodes of no element: not read
  for (std::size_t v = 0; v < local.size(); ++v)
    if (local[v] != kUnused) node_h[v] = h[local[v]];
  st.time_step = time_step_of(in, mesh, node_h);
  if (clamp) {
    st.has_depth_clamp = true;
    st.depth_clamp = *clamp;
    report_depth_clamp(in, *clamp);
  }
  return {};
}

// After 2D: the compound unions' elements back on their surfaces (with each union's target
// size), the periodic node pairs, and the mesher's warnings as diagnostics at `where`, so
// that they print in order with Printf and the progress display (the front end drops them
// below General.Verbosity 2).
MeshFailure finish_2d_elements(Interpreter& in, const CompoundSurfacePlan& compounds, ModelMesh& mesh,
                               Mesh2dResult& r2, SourceRange where) {
  KernelState& k = in.kernel();
  classify_compound_elements(k.model, compounds, mesh);
  // the quality floor may have split a curve edge
  if (!k.constraints.periodic_curves.empty() || !k.constraints.periodic_surfaces.empty()) {
    MeshError why;
    mesh.periodic = periodic_links(k.model, mesh, k.constraints, &why);
    if (!why.ok()) {
      auto [kind, message] = worded_mesh_problem(why);
      return {kind, std::move(message), {}};
    }
  }
  for (const CompoundSurfacePlan::Group& g : compounds.groups)   // the union's target size on each original
    for (std::size_t i = 0, n = r2.target_sizes.size(); i < n; ++i)
      if (r2.target_sizes[i].surface == g.union_tag) {
        for (int s : g.surfaces) r2.target_sizes.push_back({s, r2.target_sizes[i].size});
        r2.target_sizes[i].surface = 0;
      }
  for (const StageTime& t : stage_times(r2.stats)) add_stage_time(k.mesh2d_parts, t);
  // The floor's notes after the others, each in face order.
  for (bool floor : {false, true})
    for (const MeshNote& note : r2.notes)
      if (note.about_floor() == floor) report_mesh_note(in.diags(), where, note, compounds);
  return {};
}

// Meshes the model up to `dim` into the kernel state; on failure returns why. The
// mesher's warnings are reported at `where` (the Mesh statement; none for -1/-2). Every
// option is checked and every field built before the 1D mesher runs.
MeshFailure mesh_model_unguarded(Interpreter& in, int dim, SourceRange where) {
  KernelState& k = in.kernel();
  sync_geometry_options(in);  // Gmsh reads Geometry.OldRuledSurface when it meshes
  k.partition.reset();
  if (OptionRefusal refused = check_elements_across_channels(in.options()); !refused.empty())
    return {refused.kind, std::move(refused.message), set_here(k, "Mesh.ElementsAcrossChannels")};
  // The background field with the coastlines' channel widths inside its Min.
  // Shown as a stage when there is a field to set up (not for a model with sizes at points).
  const bool has_fields = (k.background_field && *k.background_field > 0) || !k.coastlines.empty();
  std::optional<StageScope> fields_stage(std::in_place, &k.clock, has_fields ? progress_sink(in) : nullptr, "fields");
  field::FieldPtr background = with_channel_sizes(in, background_size_field(in));
  fields_stage.reset();
  Mesh2dOptions opt2;
  if (dim >= 2)
    if (MeshFailure f = mesh2d_options(in, background.get(), opt2); f.failed()) return f;
  field::FieldPtr depth;
  if (MeshFailure f = depth_field_for_mesh(in, depth); f.failed()) return f;
  // Mesh.MinTimeStep: no size below the one a gravity wave crosses in the step (with a
  // margin, as the shortest edge of a good triangle is about 0.7 of its size).
  const double min_step = in.options().number("Mesh.MinTimeStep");
  if (min_step > 0 && !depth)
    return {Diag::MinTimeStepNeedsDepth, format_diag(Diag::MinTimeStepNeedsDepth, min_step),
            set_here(k, "Mesh.MinTimeStep")};
  if (min_step > 0 && background) {
    background = field::time_step_floor(background, depth, min_step, in.options().number("Mesh.TimeStepMinDepth"),
                                        kMinStepSizeFactor);
    opt2.background = background.get();
  }
  if (MeshFailure f = structured_constraints(in, dim, opt2); f.failed()) return f;
  const std::vector<field::BoundaryLayerParams> layers = boundary_layers_of(in);
  opt2.boundary_layers = layers.empty() ? nullptr : &layers;
  opt2.boundary_layer_fan_elements = static_cast<int>(in.options().number("Mesh.BoundaryLayerFanElements"));
  Mesh1dOptions opt1 = mesh1d_options(in, background.get());
  opt1.boundary_layers = opt2.boundary_layers;
  opt1.max_elements = in.options().number("Mesh.MaxElements");
  opt1.constraints = &k.constraints;   // -1 too: Gmsh's odd counts are made in 1D
  // Many 1D nodes: the faces' budgets first, on a coarse boundary, before the full 1D
  // mesh is paid for (a unit square at size 1e-7 has 4e7 boundary nodes, 2e14 triangles).
  MeshError budget;
  // `Compound Surface{...}`: the model meshed holds each group's union in place of its
  // surfaces (mesh/compound_surface.h); the elements go back to them after 2D.
  const CompoundSurfacePlan compounds = plan_compound_surfaces(k.model, k.constraints.compound_surfaces);
  const geo::Model& meshed = compounds.empty() ? k.model : compounds.model;
  for (const CompoundSurfacePlan::Declined& d : compounds.declined) report_compound_declined(in.diags(), where, d);
  if (dim >= 2)
    opt1.coarse_check = [&](const ModelMesh& coarse) {
      budget = check_face_budgets(meshed, coarse, opt2).error;
      name_compound_unions(compounds, budget);
      return budget.ok();
    };
  std::optional<StageScope> stage_1d(std::in_place, &k.clock, nullptr, "1D");
  Mesh1dResult r = mesh_curves(meshed, opt1);
  stage_1d.reset();
  if (r.error.kind == MeshErrorKind::Stopped) return failure_of(k, budget, compounds);
  if (!r.ok()) {
    auto [kind, message] = worded_1d(r.error);
    return {kind, std::move(message), provenance_notes(k, r.error)};
  }
  auto mesh = std::make_shared<ModelMesh>(std::move(r.mesh));
  // The merged files' surfaces, meshed as they are, on their points' and curves' nodes.
  if (const MeshError why = add_discrete_surfaces(k.discrete, *mesh); !why.ok()) {
    auto [kind, message] = worded_mesh_problem(why);
    return {kind, std::move(message), {}};
  }
  if (dim < 2) return finish_1d(in, std::move(mesh));
  opt2.progress = progress_sink(in);
  std::optional<StageScope> stage_2d(std::in_place, &k.clock, nullptr, "2D");
  Mesh2dResult r2 = mesh_surfaces(meshed, *mesh, opt2);
  stage_2d.reset();
  name_compound_unions(compounds, r2.error);
  if (!r2.ok()) return failure_of(k, r2.error, compounds);
  if (MeshFailure f = finish_2d_elements(in, compounds, *mesh, r2, where); f.failed()) return f;
  // Statistics against the size each face's mesher aimed at (with the extension from
  // the boundary where it is on).
  std::optional<StageScope> stage_stats(std::in_place, &k.clock, progress_sink(in), "statistics");
  MeshStats st = mesh_stats(*mesh, r2.target_sizes, static_cast<int>(in.options().number("General.NumThreads")));
  locate_worst_triangle(k.model, st);
  if (depth && min_step > 0) enforce_min_time_step(in, *mesh, *depth, min_step, where);
  if (depth)
    if (MeshFailure f = depth_and_time_step(in, *mesh, st); f.failed()) return f;
  stage_stats.reset();   // a stage of its own, not counted twice in the time line
  if (OptionRefusal refused = partition_mesh_now(in, *mesh, &st); !refused.empty())
    return {refused.kind, std::move(refused.message), set_here(k, "Mesh.NbPartitions")};
  publish_stats(in, *mesh, st);
  k.mesh = std::move(mesh);
  return {};
}

// mesh_model_unguarded, with running out of memory anywhere in the meshers (threads
// included: base/parallel rethrows on the caller) a script error like the others, so
// nothing is written; and a background field that gives a bad size (a FieldError from
// field/size_check.h) reported at the field's definition.
MeshFailure mesh_model(Interpreter& in, int dim, SourceRange where) {
  try {
    return mesh_model_unguarded(in, dim, where);
  } catch (const field::FieldError& e) {
    fail_field_error(in, e, in.kernel().background_field_at);
  } catch (const std::bad_alloc&) {
    return {Diag::OutOfMemory,
            format_diag<int, double>(Diag::OutOfMemory, dim, in.options().number("Mesh.MaxElements")),
            {}};
  }
}

// A partitioned mesh asked for in a format that cannot hold it: an error at the Save
// statement's file name, or for -o before meshing, rather than partitions dropped.
bool partitions_unheld(Interpreter& in, const io::OutputFormat& f) {
  return in.options().number("Mesh.NbPartitions") > 0 && !holds_partitions(f, in.options());
}

// The format `path` is written in when no -format names one: Mesh.Format's number, or
// with Mesh.Format 10 (auto) the file's extension; nullptr and why not in *why.
const io::OutputFormat* guess_output_format(const Options& o, const std::string& path, std::string* why) {
  const std::string ext = std::filesystem::path(path).extension().string();
  const int mesh_format = static_cast<int>(o.number("Mesh.Format"));
  const io::OutputFormat* f = nullptr;
  if (mesh_format != 10) {
    f = io::output_format_of_number(mesh_format);
  } else if (ext.empty() && base::writes_in_place(path)) {
    // Standard output ('-o -'), a FIFO or a device has no extension: the first format (MSH).
    f = &io::output_formats().front();
  } else {
    f = io::output_format_of_extension(ext);
  }
  if (!f)
    *why = ext.empty() ? fmt::format("the file name has no extension (use {})", io::output_format_extensions())
                       : fmt::format("unknown file extension '{}' (use {})", ext, io::output_format_extensions());
  return f;
}

// Writes the current mesh to `path` in `format` (see mesh_commands.h); "" or why not.
std::string save_mesh(Interpreter& in, const std::string& path, const std::string& format) {
  const KernelState& k = in.kernel();
  // The file's model (from_model_mesh: the mesh numbered as written) is the writing's
  // work too: charged to the script's own time it was most of the 'script' stage on the
  // largest meshes.
  const StageScope stage(&in.kernel().clock, progress_sink(in), "writing");
  const ModelMesh empty;
  std::vector<std::uint32_t> node_index;   // ModelMesh -> mm node, for the ocean grids' boundary strings
  const Options& o = in.options();
  // The parametric coordinates only for a file that holds them (MSH's, with the option).
  io::MeshModel mm = io::from_model_mesh(k.model, k.mesh ? *k.mesh : empty, &node_index,
                                         o.number("Mesh.SaveParametric") != 0,
                                         static_cast<int>(o.number("General.NumThreads")));
  const io::OutputFormat* f = nullptr;
  if (format.empty()) {
    std::string why;
    f = guess_output_format(o, path, &why);
    if (!f) return why;
  } else {
    f = io::find_output_format(format);
    if (!f) return fmt::format("unknown format '{}' ({})", format, io::output_format_names());
  }
  if (!f->needs_file_name.empty() && base::writes_in_place(path)) return std::string(f->needs_file_name);
  io::OutputSettings settings;
  io::MeshPartition aligned;
  if (o.number("Mesh.NbPartitions") > 0) {
    if (!holds_partitions(*f, o))
      return fmt::format("{} cannot hold the {:g} partitions Mesh.NbPartitions asks for (write MSH 4.1, VTK or UGRID "
                         "netCDF)",
                         f->name, o.number("Mesh.NbPartitions"));
    // Partitioned when meshed; again when the partition options changed since (as Gmsh's
    // PartitionMesh after a mesh), so a Save never writes other parts than the options say.
    if (std::string why = current_partition(in); !why.empty()) return why;
    settings.partition = &aligned;   // filled below, once the node coordinates dropped what they drop
    settings.split_files = o.number("Mesh.PartitionSplitMeshFiles") != 0;
    settings.partition_topology = o.number("Mesh.PartitionCreateTopology") != 0;
    if (settings.split_files && base::writes_in_place(path) && f->input == io::OutputInput::Mesh &&
        f->mesh_format == 1)
      return "Mesh.PartitionSplitMeshFiles writes one file per partition beside the name: give a file name";
  }
  // In space, before the node coordinates are rewritten for the Mesh rows.
  if (f->holds_node_data)
    if (std::string why = node_data_for_output(in, mm, settings.node_data); !why.empty()) return why;
  switch (f->input) {
    case io::OutputInput::OceanGrid:
      if (std::string why = ocean_grid_options(in, path, mm, node_index, settings.ocean); !why.empty()) return why;
      break;
    case io::OutputInput::Picture:
      if (std::string why = picture_options(in, mm, settings.picture); !why.empty()) return why;
      break;
    case io::OutputInput::Mesh:
      if (std::string why = apply_node_coordinates(in, mm); !why.empty()) return why;
      break;
  }
  node_index = {};   // read by the ocean grids' options only: not held through the writing
  if (settings.partition) aligned = io::aligned_partition(*k.partition, mm);
  settings.binary = o.number("Mesh.Binary") != 0;
  settings.save_all = o.number("Mesh.SaveAll") != 0;
  settings.save_parametric = o.number("Mesh.SaveParametric") != 0;
  const double version = f->msh_file_version != 0 ? f->msh_file_version : o.number("Mesh.MshFileVersion");
  settings.msh_version = version < 3 ? 22 : 41;
  settings.threads = static_cast<int>(o.number("General.NumThreads"));
  std::string error;
  return f->write(mm, settings, path, &error) ? std::string{} : error;
}

void exec_mesh(Interpreter& in, StmtId id, const CommandStmt& c) {
  const Stmt& s = in.ast().stmt(id);
  const double n = c.arg.valid() ? in.eval_number(c.arg) : 2;
  if (n >= 3) {
    in.not_supported_stmt(id, "Mesh 3");
    return;
  }
  const MeshFailure f = mesh_model(in, n >= 2 ? 2 : 1, s.range);
  if (f.failed()) in.fail_message_with_notes(s.range, f.kind, f.message, f.notes);
}

// An ocean-model grid (fort.14, hgrid.gr3) holds a depth per node that the model runs on:
// written without Mesh.DepthField it is all zeros, which loads and is wrong, so say so.
void warn_if_no_depth(Interpreter& in, const io::OutputFormat& f, const std::string& path, SourceRange at) {
  if (f.depth_required && !(in.options().number("Mesh.DepthField") > 0))
    in.diags().report(at, Diag::OutputWithoutDepth, path, f.name);
}

void exec_save(Interpreter& in, StmtId id, const CommandStmt& c) {
  const Stmt& s = in.ast().stmt(id);
  std::string name = in.eval_string(c.arg);
  // Relative to the script (Gmsh: relative to the directory of the file being parsed).
  std::filesystem::path p(name);
  if (p.is_relative()) p = std::filesystem::path(in.sources().path(s.range.file)).parent_path() / p;
  const SourceRange at = c.arg.valid() ? in.ast().expr(c.arg).range : s.range;
  std::string why;
  if (const io::OutputFormat* f = guess_output_format(in.options(), p.string(), &why)) {
    warn_if_no_depth(in, *f, name, at);
    if (partitions_unheld(in, *f))
      in.fail_fmt(at, Diag::PartitionsNotHeld, name, f->name, in.options().number("Mesh.NbPartitions"));
  }
  if (const std::string err = save_mesh(in, p.string(), ""); !err.empty())
    in.fail_fmt(at, Diag::FileWriteError, name, err);
}

// `PartitionMesh N;` (Gmsh's GModel::partitionMesh): Mesh.NbPartitions = N, and the 2D mesh
// partitioned now; an error at the statement without a 2D mesh or with a bad N.
void exec_partition_mesh(Interpreter& in, StmtId id, const CommandStmt& c) {
  const Stmt& s = in.ast().stmt(id);
  const double n = in.eval_number(c.arg);
  const SourceRange at = in.ast().expr(c.arg).range;
  if (!(n >= 1) || n != std::floor(n))
    in.fail(at, Diag::PartitionMeshCount, n);
  if (OptionRefusal err = in.options().set_number("Mesh.NbPartitions", n); !err.empty())
    in.fail_message(at, err.kind, std::move(err.message));
  KernelState& k = in.kernel();
  k.option_set_at["Mesh.NbPartitions"] = s.range;
  if (!k.mesh || !k.has_mesh_stats)
    in.fail(s.range, Diag::PartitionMeshNoMesh);
  k.partition.reset();
  if (OptionRefusal r = partition_mesh_now(in, *k.mesh, &k.mesh_stats); !r.empty())
    in.fail_message(s.range, r.kind, std::move(r.message));
}

}  // namespace

bool exec_mesh_command(Interpreter& in, StmtId id, std::string_view command) {
  const Stmt& s = in.ast().stmt(id);
  if (const auto* c = std::get_if<CommandStmt>(&s.node)) {
    if (command == "Mesh") {
      exec_mesh(in, id, *c);
      return true;
    }
    if (command == "Save" && c->arg.valid()) {
      exec_save(in, id, *c);
      return true;
    }
    if (command == "Merge" && c->arg.valid()) {
      exec_merge(in, id, *c);   // merge.cpp
      return true;
    }
    // Merge makes the discrete curves' end points as it reads a mesh file (merge_mesh.cpp),
    // so that Gmsh's `CreateTopology;` after it has nothing left to do.
    if (command == "CreateTopology" && !c->arg.valid()) return true;
    if (command == "CreateGeometry" && !c->arg.valid()) {
      exec_create_geometry(in, id);
      return true;
    }
    if (command == "PartitionMesh" && c->arg.valid()) {
      exec_partition_mesh(in, id, *c);
      return true;
    }
  }
  static constexpr std::array<std::string_view, 18> kKnown = {
      "Mesh", "Save", "Merge", "Print", "SystemCall", "CreateDir", "OptimizeMesh", "SetName",
      "SetOrder", "Sleep", "PartitionMesh", "RefineMesh", "RecombineMesh", "RenumberMeshNodes",
      "RenumberMeshElements", "SyncModel", "BoundingBox", "Coherence"};
  for (std::string_view k : kKnown) {
    if (k == command) {
      check_stmt_exprs(in, id);
      in.not_supported_stmt(id, command);
      return true;
    }
  }
  return false;
}

void exec_mesh_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  check_stmt_exprs(in, id);
  switch (s.kind()) {
    case StmtKind::Plugin: in.not_supported_stmt(id, "Plugin"); break;
    case StmtKind::View: in.display_only_stmt(id, "View"); break;
    case StmtKind::Color: in.display_only_stmt(id, "Color"); break;
    case StmtKind::Visibility: in.display_only_stmt(id, "Hide/Show"); break;
    default: in.not_supported_stmt(id, "Coherence Mesh"); break;
  }
}

std::vector<StageTime> run_stages(Interpreter& in) {
  const KernelState& k = in.kernel();
  std::vector<StageTime> out;
  for (const StageTime& t : k.clock.stages()) {
    if (t.name != "2D") {
      out.push_back(t);
      continue;
    }
    // The mesher's own stages, and what it spent outside them (its set-up, the checks
    // between stages) so that the parts still add up to the "2D" stage.
    double parts = 0;
    for (const StageTime& p : k.mesh2d_parts) out.push_back(p), parts += p.seconds;
    if (t.seconds - parts >= 0.0005) out.push_back({"2D other", t.seconds - parts});
  }
  return fold_small_stages(out, "field ", kMinFieldSeconds, "fields");
}

std::string finish_run(Interpreter& in, bool print_time) {
  KernelState& k = in.kernel();
  const std::vector<StageTime> stages = run_stages(in);
  if (print_time && in.options().number("General.Verbosity") >= 4) {
    std::fflush(stdout);
    std::fputs(format_time_line(stages).c_str(), stderr);
    std::fflush(stderr);
  }
  if (k.has_curve_stats) return curve_stats_json(k.curve_stats, stages);
  if (!k.has_mesh_stats) return {};
  MeshStats st = k.mesh_stats;
  st.stages = stages;
  st.stages_cpu = fold_small_stages(k.clock.cpu_stages(), "field ", kMinFieldSeconds, "fields");
  return stats_json(st);
}

bool mesh_after_scripts(Interpreter& in, int dim) {
  Diagnostics& diags = in.diags();
  if (dim >= 3) {
    diags.report_message(SourceRange{}, Diag::NotSupportedYet, "'-3' is not supported: stereomesh meshes surfaces");
    return false;
  }
  MeshFailure f;
  try {
    f = mesh_model(in, dim, SourceRange{});
  } catch (const RuntimeError& err) {   // e.g. the background field cannot be built
    auto h = diags.report_message(err.range, err.kind, err.message);
    for (const DiagNote& n : err.notes) h.note(n.range, n.message);
    return false;
  }
  if (f.failed()) {
    // No statement asked for the mesh: the entity's statement is the place to point at.
    const SourceRange at = f.notes.empty() ? SourceRange{} : f.notes.front().range;
    auto h = diags.report_message(at, f.kind, f.message);
    for (std::size_t i = 1; i < f.notes.size(); ++i) h.note(f.notes[i].range, f.notes[i].message);
    return false;
  }
  return true;
}

std::string default_mesh_output(const std::string& first_script, const std::string& format) {
  std::filesystem::path p(first_script);
  const io::OutputFormat* row = io::find_output_format(format);
  if (!row) row = &io::output_formats().front();
  if (!row->default_file_name.empty()) p.replace_filename(std::string(row->default_file_name));
  else p.replace_extension(std::string(row->extension));
  return p.string();
}

bool mesh_from_command_line(Interpreter& in, int dim, const std::string& output, const std::string& format,
                            const std::string& first_script) {
  Diagnostics& diags = in.diags();
  if (dim >= 3) return mesh_after_scripts(in, dim);   // refused there
  // The file and its format are known before meshing: a name that picks no format is
  // refused now rather than after minutes of meshing, and a depthless ocean grid said.
  const std::string path = output.empty() ? default_mesh_output(first_script, format) : output;
  {
    std::string why;
    const io::OutputFormat* row =
        format.empty() ? guess_output_format(in.options(), path, &why) : io::find_output_format(format);
    if (!row) {
      diags.report(SourceRange{}, Diag::FileWriteError, path, why.empty() ? "unknown format '" + format + "'" : why);
      return false;
    }
    warn_if_no_depth(in, *row, path, SourceRange{});
    if (partitions_unheld(in, *row)) {
      diags.report(SourceRange{}, Diag::PartitionsNotHeld, path, row->name, in.options().number("Mesh.NbPartitions"));
      return false;
    }
  }
  if (!mesh_after_scripts(in, dim)) return false;
  std::string err;
  try {
    err = save_mesh(in, path, format);
  } catch (const RuntimeError& e) {   // e.g. the depth field cannot be built
    auto h = diags.report_message(e.range, e.kind, e.message);
    for (const DiagNote& n : e.notes) h.note(n.range, n.message);
    return false;
  }
  if (!err.empty()) {
    diags.report(SourceRange{}, Diag::FileWriteError, path, err);
    return false;
  }
  return true;
}

}  // namespace sm::interp
