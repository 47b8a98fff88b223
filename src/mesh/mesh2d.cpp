// The face driver of 2D meshing (paper section 3.3): boundary nodes in the face's plane,
// Delaunay + edge recovery + hole removal, del2d/front2d refinement with the size converted
// to the plane (h / lambda on a PolarSphere; large faces in parts on threads, partition.h),
// Laplacian smoothing, 3D output.
#include "mesh/mesh2d.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "base/elapsed.h"
#include "base/parallel.h"
#include "exact/predicates.h"
#include "exact/triangle_rho.h"
#include "mesh/cdt.h"
#include "mesh/delaunay.h"
#include "mesh/face_plane.h"
#include "mesh/face_sizing.h"
#include "mesh/frontal.h"
#include "mesh/meshadapt.h"
#include "mesh/modify/optimize.h"
#include "mesh/modify/smooth.h"
#include "mesh/partition.h"
#include "mesh/quality_floor.h"
#include "mesh/recombine.h"
#include "mesh/refine.h"
#include "mesh/transfinite_surface.h"

namespace sm {
namespace {

constexpr std::uint32_t kNoLocal = 0xFFFFFFFFu;
// del2d's bound on circumradius / size. refine.h's 1/sqrt2 leaves edges short (square
// with holes, lc 0.03: median edge/size 0.92, 94.0% in [0.7, 1.4]); 0.76 centres them
// (0.98, 96.9%) but on the world ocean gives fewer well-shaped triangles than Gmsh (74.6%
// rho > 0.9 against 76.5%); 0.73 keeps both: square 95.6% in range, world 76.2% rho > 0.9
// and 95.4% in range (Gmsh: 91.5%).
constexpr double kDel2dRadiusLimit = 0.73;

// A face refined in one piece gets its own progress stage from this estimated size on
// (smaller ones refine in well under a tenth of a second).
constexpr std::uint64_t kNestedProgressTriangles = 65536;

// One closed chain of global nodes (first not repeated) with the curve of each edge.
struct Chain {
  std::vector<std::uint32_t> nodes;
  std::vector<int> edge_curve;
};

// Appends the face's elements to `out`, their corners mapped by `node` (local -> global
// node) and reversed when `flip` (the plane's counter-clockwise is not the outward normal).
template <class NodeOf>
void append_elements(SurfaceMesh& out, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                     const std::vector<std::array<std::uint32_t, 4>>& quads, bool flip, const NodeOf& node) {
  out.triangles.reserve(out.triangles.size() + triangles.size());
  for (const auto& t : triangles) {
    const std::uint32_t a = node(t[0]), b = node(t[1]), c = node(t[2]);
    out.triangles.push_back(flip ? std::array<std::uint32_t, 3>{a, c, b} : std::array<std::uint32_t, 3>{a, b, c});
  }
  for (const auto& q : quads) {
    const std::uint32_t a = node(q[0]), b = node(q[1]), c = node(q[2]), d = node(q[3]);
    out.quads.push_back(flip ? std::array<std::uint32_t, 4>{a, d, c, b} : std::array<std::uint32_t, 4>{a, b, c, d});
  }
}

// Whether model surface `tag` is bounded by curve c or embeds it.
bool surface_uses_curve(const geo::Model& model, int tag, int c) {
  const geo::ModelSurface* s = model.surface(tag);
  if (!s) return false;
  for (int l : s->loops)
    if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
      for (int lc : loop->curves)
        if (std::abs(lc) == c) return true;
  return std::find(s->embedded_curves.begin(), s->embedded_curves.end(), c) != s->embedded_curves.end();
}

class FaceMesher {
 public:
  /// local_of: global node -> local vertex, all kNoLocal; left so again on return.
  FaceMesher(const geo::Model& model, ModelMesh& mesh, const Mesh2dOptions& opt, double bbox, Mesh2dResult& res,
             std::vector<std::uint32_t>& local_of)
      : model_(model), mesh_(mesh), opt_(opt), bbox_(bbox), res_(res), local_of_(local_of) {}
  ~FaceMesher() {
    for (std::uint32_t node : global_)
      if (node < local_of_.size()) local_of_[node] = kNoLocal;
  }
  /// The pipeline: collect_loops, make_plane, triangulate_boundary, make_sizing,
  /// check_budget, then refine_face, smooth, optimize and output.
  bool run(const geo::ModelSurface& s);
  /// Only up to the element budget: run() stops once the estimate is checked.
  void estimate_only() { estimate_only_ = true; }

 private:
  /// Sets the error: this surface, then `curves`, the message, the place.
  bool fail(std::string msg, std::optional<Vec3> where = std::nullopt, std::initializer_list<int> curves = {});
  /// "lon X, lat Y" of a point of the face (on a geometry), else "(x, y, z)".
  std::string where_text(Vec3 p) const;
  bool collect_loops(const geo::ModelSurface& s);
  bool make_plane();
  std::uint32_t local(std::uint32_t node);
  /// Local vertices (loops, embedded curves, embedded points, first occurrence order),
  /// Delaunay of them, edge recovery and hole removal.
  bool triangulate_boundary();
  /// The face's sizing once its boundary is recovered (the plane and boundary sizes are
  /// final then).
  void make_sizing();
  /// The estimated triangle count when something needs it (the budget, the partitioning,
  /// the progress display); false when it is over Mesh.MaxElements.
  bool check_budget(std::uint64_t& estimate);
  /// Refinement (del2d / front2d, in parts for a large face) or meshadapt.
  bool refine_face(std::uint64_t estimate);
  bool refine(const std::function<void(std::span<const Vec2>, std::span<double>)>& size_at, std::uint64_t estimate);
  /// RefineOptions::vertex_size_scale of this face: 1 / lambda on a sphere, null on a plane.
  PlaneSizeFn plane_scale() const;
  void smooth();
  void optimize();
  /// The quality floor (Mesh2dOptions::quality_floor), then the quality pass again where
  /// it changed something; its report into res_.quality_warnings.
  void raise_floor();
  void report_floor(const QualityFloorResult& r);
  /// The point in space of local vertex v: its node, or its plane point mapped.
  Vec3 space_of(VertexId v) const;
  /// The curve of the face edge between local vertices a and b (0: none).
  int curve_of(VertexId a, VertexId b) const;
  /// Interior nodes to 3D, triangles oriented (paired into quadrangles where the surface
  /// is recombined), the surface's mesh and target size kept.
  void output();
  /// A transfinite surface: its boundary chain filled (transfinite_surface.h), in place
  /// of the unstructured pipeline.
  bool run_transfinite(const geo::ModelSurface& s, const TransfiniteSurfaceSpec& spec);
  bool recombined() const { return opt_.constraints && opt_.constraints->recombines(tag_); }

  const geo::Model& model_;
  ModelMesh& mesh_;
  const Mesh2dOptions& opt_;
  double bbox_;
  Mesh2dResult& res_;
  int tag_ = 0;
  FacePlane plane_;
  std::vector<Chain> chains_;                 // [0] outer, then holes
  std::vector<std::uint32_t> emb_points_;     // global nodes
  std::vector<Chain> emb_curves_;             // open chains (edge i joins nodes i, i+1)
  std::vector<std::uint32_t> global_;         // local vertex -> global node
  std::vector<std::uint32_t>& local_of_;      // global node -> local vertex (shared scratch)
  std::vector<Edge> edges_;                   // boundary and embedded edges (local vertices)
  std::vector<int> edge_curve_;               // the curve of each
  std::uint32_t fixed_count_ = 0;             // local vertices [0, fixed_count_): the input nodes
  TriangleStore m_;
  TriangleStore hull_;                        // m_ before hole removal (extension from the boundary)
  std::shared_ptr<FaceSizing> sizing_ = std::make_shared<FaceSizing>();
  std::atomic<std::uint64_t> size_evaluations_{0};
  bool smoothed_ = false;                     // meshadapt smooths in each of its rounds
  // The quality floor's curve splits: the curve of each boundary edge (local vertex pair,
  // smaller first; embedded curves too), the split asked last.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_curve_of_;
  struct PendingSplit {
    int curve = 0;
    std::size_t k = 0;   // between cm.nodes[k] and cm.nodes[k + 1]
    double t = 0;
    MeshNode node;
  } pending_;
  std::vector<std::pair<int, std::uint32_t>> floor_nodes_;   // (curve, node) the floor added
  bool estimate_only_ = false;
};

bool FaceMesher::fail(std::string msg, std::optional<Vec3> where, std::initializer_list<int> curves) {
  MeshError& e = res_.error;
  e.kind = MeshErrorKind::Failed;
  e.add_entity(2, tag_);
  for (int c : curves) e.add_entity(1, c);
  e.message = fmt::format("surface {}: {}", tag_, msg);
  if (where) {
    e.xyz = *where;
    if (plane_.geom) {
      e.has_lonlat = true;
      e.where = plane_.lonlat(*where);
      e.message += fmt::format(" near lon {:.6f}, lat {:.6f}", e.where.lon, e.where.lat);
    } else {
      e.message += fmt::format(" near ({}, {}, {})", where->x, where->y, where->z);
    }
  }
  return false;
}

std::string FaceMesher::where_text(Vec3 p) const {
  if (!plane_.geom) return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z);
  const geo::LonLat ll = plane_.lonlat(p);
  return fmt::format("lon {:.4f}, lat {:.4f}", ll.lon, ll.lat);
}

bool FaceMesher::collect_loops(const geo::ModelSurface& s) {
  // Islands below the mesh size (hole chains of fewer than 3 mesh edges): one warning
  // for the face, naming the largest, rather than one line per island.
  struct Island {
    int loop;
    double span;   // distance between its nodes: a lower bound of its size
    Vec3 at;
  };
  std::vector<Island> islands;
  for (std::size_t li = 0; li < s.loops.size(); ++li) {
    const geo::ModelCurveLoop* loop = model_.curve_loop(std::abs(s.loops[li]));
    if (!loop) return fail(fmt::format("curve loop {} does not exist", std::abs(s.loops[li])));
    std::vector<int> curves = loop->curves;
    if (s.loops[li] < 0) {
      std::reverse(curves.begin(), curves.end());
      for (int& c : curves) c = -c;
    }
    // A loop may hold several closed chains (Gmsh's subloops): a chain ends when it
    // returns to its first node.
    Chain ch;
    for (int sc : curves) {
      const auto it = mesh_.curves.find(std::abs(sc));
      if (it == mesh_.curves.end()) return fail(fmt::format("curve {} has no 1D mesh", std::abs(sc)));
      std::vector<std::uint32_t> nodes = it->second.nodes;
      if (nodes.size() < 2) continue;   // collapsed (mesh/mesh1d.cpp): its ends are one node
      if (sc < 0) std::reverse(nodes.begin(), nodes.end());
      if (!ch.nodes.empty() && ch.nodes.back() != nodes.front())
        return fail(fmt::format("curve loop {} is not connected at curve {}", loop->tag, sc));
      for (std::size_t k = ch.nodes.empty() ? 0 : 1; k < nodes.size(); ++k) ch.nodes.push_back(nodes[k]);
      ch.edge_curve.insert(ch.edge_curve.end(), nodes.size() - 1, std::abs(sc));
      if (ch.nodes.size() > 1 && ch.nodes.back() == ch.nodes.front()) {
        ch.nodes.pop_back();
        if (ch.nodes.size() < 3 && (li > 0 || !chains_.empty())) {
          // An island below the mesh size meshed as two edges encloses nothing: left out
          // (Gmsh does the same).
          const Vec3 a = mesh_.nodes[ch.nodes.front()].xyz, b = mesh_.nodes[ch.nodes.back()].xyz;
          islands.push_back({loop->tag, norm(b - a), (a + b) * 0.5});
        } else if (ch.nodes.size() < 3) {
          return fail(fmt::format("curve loop {} has fewer than 3 boundary nodes", loop->tag),
                      mesh_.nodes[ch.nodes.front()].xyz);
        } else {
          chains_.push_back(std::move(ch));
        }
        ch = Chain{};
      }
    }
    if (!ch.nodes.empty()) return fail(fmt::format("curve loop {} does not close", loop->tag));
  }
  if (!islands.empty()) {
    // The first island of the largest span: deterministic for equal spans.
    std::size_t big = 0;
    for (std::size_t i = 1; i < islands.size(); ++i)
      if (islands[i].span > islands[big].span) big = i;
    constexpr std::size_t kListed = 8;
    std::string loops;
    for (std::size_t i = 0; i < std::min(islands.size(), kListed); ++i)
      loops += fmt::format("{}{}", i ? ", " : "", islands[i].loop);
    if (islands.size() > kListed) loops += fmt::format(" and {} more", islands.size() - kListed);
    const bool one = islands.size() == 1;
    res_.warnings.push_back(fmt::format(
        "surface {}: {} island{} smaller than the mesh size {} left out ({} closed curve{} got fewer than 3 mesh "
        "edges; {}near {}): hole loop{} {}",
        tag_, islands.size(), one ? "" : "s", one ? "is" : "are", one ? "its" : "their", one ? "" : "s",
        one ? "" : "largest ", where_text(islands[big].at), one ? "" : "s", loops));
  }
  if (chains_.empty()) return fail("no boundary loop");
  for (int p : s.embedded_points) {
    const auto it = mesh_.vertex_node.find(p);
    if (it == mesh_.vertex_node.end()) return fail(fmt::format("embedded point {} has no node", p));
    emb_points_.push_back(it->second);
  }
  for (int c : s.embedded_curves) {
    const auto it = mesh_.curves.find(c);
    if (it == mesh_.curves.end()) return fail(fmt::format("embedded curve {} has no 1D mesh", c));
    Chain ch;
    ch.nodes = it->second.nodes;
    ch.edge_curve.assign(ch.nodes.size() - 1, c);
    emb_curves_.push_back(std::move(ch));
  }
  return true;
}

bool FaceMesher::make_plane() {
  std::vector<const std::vector<std::uint32_t>*> curves;
  for (const auto* group : {&chains_, &emb_curves_})
    for (const Chain& ch : *group) curves.push_back(&ch.nodes);
  const double tol = std::max(model_.options().tolerance * bbox_, 1e-12 * bbox_);
  const std::optional<FacePlaneProblem> p = make_face_plane(plane_, mesh_, curves, emb_points_, tol);
  return p ? fail(p->message, p->where) : true;
}

std::uint32_t FaceMesher::local(std::uint32_t node) {
  if (local_of_[node] == kNoLocal) {
    local_of_[node] = static_cast<std::uint32_t>(global_.size());
    global_.push_back(node);
    m_.add_vertex(plane_.node_plane(mesh_.nodes[node]));
  }
  return local_of_[node];
}

// del2d or front2d on the face: in one piece, or in parts (partition.h) when the estimated
// triangle count reaches opt_.partition.min_triangles. The part count depends on the
// estimate only, so the mesh is the same for every thread count.
PlaneSizeFn FaceMesher::plane_scale() const {
  if (!plane_.geom) return nullptr;
  const std::shared_ptr<const FaceSizing> sizing = sizing_;
  return [sizing](std::span<const Vec2> p, std::span<double> h) {
    for (std::size_t i = 0; i < p.size(); ++i) h[i] = 1 / sizing->plane.lambda(p[i]);
  };
}

bool FaceMesher::refine(const std::function<void(std::span<const Vec2>, std::span<double>)>& size_at,
                        std::uint64_t estimate) {
  RefineOptions ro;
  ro.max_vertices = opt_.max_vertices_per_face;
  ro.size_at = size_at;
  // The boundary sizes extended into the face size a triangle by its vertices, as Gmsh's
  // refiners do (RefineOptions::vertex_size_at); the rest of the size at its circumcentre.
  std::shared_ptr<PlaneSizes> without_ext, ext_only;
  if (opt_.size.extend_from_boundary != 0) {
    without_ext = std::make_shared<PlaneSizes>(*sizing_, &size_evaluations_, PlaneSizes::Part::WithoutExtension);
    ext_only = std::make_shared<PlaneSizes>(*sizing_, &size_evaluations_, PlaneSizes::Part::ExtensionOnly);
    ro.size_at = [without_ext](std::span<const Vec2> p, std::span<double> h) { (*without_ext)(p, h); };
    ro.vertex_size_at = [ext_only](std::span<const Vec2> p, std::span<double> h) { ext_only->on_surface(p, h); };
    ro.vertex_size_scale = plane_scale();
  }
  const bool frontal = opt_.algorithm == Mesh2dAlgorithm::Frontal;
  if (opt_.radius_limit > 0) ro.radius_limit = opt_.radius_limit;
  else if (!frontal) ro.radius_limit = kDel2dRadiusLimit;
  const bool partitioning = opt_.partition.min_triangles > 0;
  if (partitioning && estimate >= opt_.partition.min_triangles) {
    ro.size_at = nullptr;
    ro.vertex_size_at = nullptr;
    // Each part carries the extension by its vertices too, with functions of its own.
    std::function<void(RefineOptions&)> part_sizes;
    if (opt_.size.extend_from_boundary != 0)
      part_sizes = [this](RefineOptions& o) {
        auto w = std::make_shared<PlaneSizes>(*sizing_, &size_evaluations_, PlaneSizes::Part::WithoutExtension);
        auto x = std::make_shared<PlaneSizes>(*sizing_, &size_evaluations_, PlaneSizes::Part::ExtensionOnly);
        o.size_at = [w](std::span<const Vec2> p, std::span<double> h) { (*w)(p, h); };
        o.vertex_size_at = [x](std::span<const Vec2> p, std::span<double> h) { x->on_surface(p, h); };
        o.vertex_size_scale = plane_scale();
      };
    const auto make_size = [this]() -> PlaneSizeFn {
      auto sizes = std::make_shared<PlaneSizes>(*sizing_, &size_evaluations_);
      return [sizes](std::span<const Vec2> p, std::span<double> h) { (*sizes)(p, h); };
    };
    // "2D refine", nested in "2D", one unit per part: a large face is one unit of "2D"
    // that would otherwise show nothing for seconds. Reported from this thread only.
    bool nested = false;
    const auto on_parts = [this, &nested](std::uint32_t done, std::uint32_t parts) {
      if (!opt_.progress) return;
      if (!nested) progress_begin(opt_.progress, "2D refine", parts), nested = true;
      progress_update(opt_.progress, done);
    };
    const PartitionResult pr = refine_partitioned(m_, ro, frontal ? PartRefiner::Frontal : PartRefiner::Del2d,
                                                  make_size, opt_.partition, resolve_thread_count(opt_.threads),
                                                  on_parts, part_sizes);
    if (nested) progress_end(opt_.progress);
    res_.stats.inserted += pr.stats.refine.inserted;
    res_.stats.rejected += pr.stats.refine.rejected;
    res_.stats.parts += pr.stats.parts;
    res_.stats.estimated_triangles += pr.stats.estimate;
    ++res_.stats.partitioned_faces;
    if (!pr.ok()) return fail("refinement failed: " + pr.error);
    // Parts are Delaunay inside; smoothing ends with flips that make the seams so too.
    if (opt_.smoothing <= 0) make_delaunay(m_);
    return true;
  }
  // A large face in one piece: "2D refine" nested in "2D" in estimated triangles, told
  // by the refiner every 64k insertions (done is capped at the estimate, which it may pass).
  const bool nested = opt_.progress && estimate >= kNestedProgressTriangles;
  if (nested) {
    progress_begin(opt_.progress, "2D refine", estimate);
    ro.on_progress = [this, estimate](std::uint64_t triangles) {
      progress_update(opt_.progress, std::min(triangles, estimate));
    };
  }
  RefineResult rf;
  if (frontal) rf = refine_front2d(m_, ro);
  else rf = refine_del2d(m_, ro);
  if (nested) {
    if (rf.ok()) progress_update(opt_.progress, estimate);
    progress_end(opt_.progress);
  }
  res_.stats.inserted += rf.stats.inserted;
  res_.stats.rejected += rf.stats.rejected;
  if (!rf.ok()) return fail("refinement failed: " + rf.error);
  return true;
}

bool FaceMesher::run(const geo::ModelSurface& s) {
  tag_ = s.tag;
  if (s.filling && s.loops.size() > 1)
    return fail(fmt::format("a filling 'Surface' with holes (curve loop {}{}) is not meshed yet (Gmsh meshes it in "
                            "the (u,v) of its first loop's patch)",
                            std::abs(s.loops[1]), s.loops.size() > 2 ? fmt::format(" and {} more", s.loops.size() - 2) : ""));
  if (opt_.constraints)
    if (const auto it = opt_.constraints->surfaces.find(s.tag); it != opt_.constraints->surfaces.end()) {
      if (estimate_only_) return true;   // a grid: its count is the curves' product
      return run_transfinite(s, it->second);
    }
  if (s.filling)
    return fail("a filling 'Surface' is meshed only as a transfinite one: add 'Transfinite Surface{" +
                std::to_string(s.tag) + "};' (or use 'Plane Surface')");
  plane_.geom = s.geometry ? model_.geometry(s.geometry) : nullptr;
  if (s.geometry && !plane_.geom) return fail(fmt::format("surface geometry {} does not exist", s.geometry));
  auto t0 = std::chrono::steady_clock::now();
  if (!collect_loops(s) || !make_plane() || !triangulate_boundary()) return false;
  make_sizing();
  std::uint64_t estimate = 0;
  if (!check_budget(estimate)) return false;
  res_.stats.seconds_boundary += seconds_since(t0);
  if (estimate_only_) return true;
  if (opt_.algorithm == Mesh2dAlgorithm::InitialOnly) {   // Gmsh's "initial mesh only"
    output();
    return true;
  }

  t0 = std::chrono::steady_clock::now();
  if (!refine_face(estimate)) return false;
  res_.stats.size_evaluations += size_evaluations_.exchange(0);
  res_.stats.seconds_refine += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  smooth();
  res_.stats.seconds_smooth += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  optimize();
  res_.stats.seconds_optimize += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  raise_floor();
  res_.stats.seconds_floor += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  output();
  res_.stats.seconds_output += seconds_since(t0);
  return true;
}

bool FaceMesher::triangulate_boundary() {
  // The scratch map is shared by all faces and reset entry by entry (O(face) per face).
  local_of_.resize(mesh_.nodes.size(), kNoLocal);
  std::vector<Loop> loops;
  for (std::size_t ci = 0; ci < chains_.size(); ++ci) {
    Loop L;
    L.hole = ci > 0;
    for (std::uint32_t node : chains_[ci].nodes) L.v.push_back(VertexId{local(node)});
    for (std::size_t k = 0; k < L.v.size(); ++k) {
      edges_.push_back({L.v[k], L.v[(k + 1) % L.v.size()]});
      edge_curve_.push_back(chains_[ci].edge_curve[k]);
    }
    loops.push_back(std::move(L));
  }
  for (const Chain& ch : emb_curves_)
    for (std::size_t k = 0; k + 1 < ch.nodes.size(); ++k) {
      edges_.push_back({VertexId{local(ch.nodes[k])}, VertexId{local(ch.nodes[k + 1])}});
      edge_curve_.push_back(ch.edge_curve[k]);
    }
  for (std::uint32_t node : emb_points_) local(node);
  fixed_count_ = m_.num_vertices();

  const DelaunayResult dr = delaunay(m_);
  if (!dr.ok()) return fail("Delaunay of the boundary nodes failed: " + dr.error);
  if (!dr.duplicates.empty()) {
    const std::uint32_t a = global_[dr.duplicates[0].dup.value], b = global_[dr.duplicates[0].kept.value];
    return fail(fmt::format("two distinct boundary nodes ({} and {}) at the same place", a, b), mesh_.nodes[a].xyz);
  }
  const PlanarGeometry g{&m_.xy};
  const RecoverResult rr = recover_edges(m_, g, edges_);
  if (!rr.ok()) return fail("boundary recovery failed: " + rr.error);
  if (!rr.crossings.empty()) {
    const EdgeCrossing& x = rr.crossings[0];
    const Edge e = edges_[x.edge];
    const int other = x.other != kNoEdge ? edge_curve_[x.other] : 0;
    return fail(fmt::format("boundary edges of curves {} and {} cross", edge_curve_[x.edge], other),
                mesh_.nodes[global_[e.first.value]].xyz, {edge_curve_[x.edge], other});
  }
  if (!rr.touching.empty()) {
    const VertexOnEdge& x = rr.touching[0];
    return fail(fmt::format("a boundary node lies on an edge of curve {}", edge_curve_[x.edge]),
                mesh_.nodes[global_[x.v.value]].xyz, {edge_curve_[x.edge]});
  }
  // The sizes extended from the boundary are interpolated in the whole recovered
  // triangulation, holes and the hull outside the face included: a walk in it always
  // reaches the point, where one in the face alone stops at a hole and would give the
  // hole's sizes to everything behind it.
  if (opt_.size.extend_from_boundary != 0) hull_ = m_;
  const DomainResult dom = remove_outside(m_, g, loops);
  if (!dom.ok()) return fail("hole removal failed: " + dom.error);
  return true;
}

void FaceMesher::make_sizing() {
  FaceSizing& sz = *sizing_;
  sz.tag = tag_;
  sz.bbox = bbox_;
  sz.size = opt_.size;
  sz.background = opt_.background;
  sz.plane = plane_;
  set_boundary_sizes(sz, std::move(hull_), fixed_count_, edges_, global_, mesh_, model_, estimate_only_);
  hull_ = TriangleStore{};
}

bool FaceMesher::check_budget(std::uint64_t& estimate) {
  // The estimate uses its own evaluator: the refiner's walk hints stay as without it. It
  // is counted in the size evaluations only when partitioning uses it.
  const bool partitioning = opt_.partition.min_triangles > 0 && opt_.algorithm != Mesh2dAlgorithm::MeshAdapt;
  if (!(partitioning || opt_.progress || opt_.max_elements > 0)) return true;
  PlaneSizes estimate_sizes(*sizing_, partitioning ? &size_evaluations_ : nullptr);
  const PlaneSizeFn estimate_at = [&estimate_sizes](std::span<const Vec2> p, std::span<double> h) {
    estimate_sizes(p, h);
  };
  estimate = estimate_triangles(m_, estimate_at);
  if (opt_.max_elements > 0 && static_cast<double>(estimate) > opt_.max_elements) {
    fail(fmt::format("it would get about {:.1e} triangles, over the limit of {:g}", static_cast<double>(estimate),
                     opt_.max_elements));
    res_.error.kind = MeshErrorKind::LimitExceeded;
    res_.error.count = static_cast<double>(estimate);
    res_.error.limit = opt_.max_elements;
    return false;
  }
  return true;
}

bool FaceMesher::refine_face(std::uint64_t estimate) {
  PlaneSizes sizes(*sizing_, &size_evaluations_);
  const auto size_at = [&sizes](std::span<const Vec2> p, std::span<double> h) { sizes(p, h); };
  if (opt_.algorithm != Mesh2dAlgorithm::MeshAdapt) return refine(size_at, estimate);
  // Meshadapt is serial: its rounds of split/collapse/swap act on the whole face.
  MeshAdaptOptions mo;
  mo.size_at = size_at;
  mo.smoothing_passes = std::max(0, opt_.smoothing);
  mo.max_vertices = opt_.max_vertices_per_face;
  const MeshAdaptResult ma = mesh_adapt(m_, mo);
  if (!ma.ok()) return fail("meshadapt failed: " + ma.error);
  res_.stats.inserted += ma.stats.splits;
  smoothed_ = true;
  return true;
}

void FaceMesher::smooth() {
  if (opt_.smoothing <= 0 || smoothed_) return;
  // smooth_laplacian keeps vertices of constrained edges in place; an isolated embedded
  // point is on none and would move: such faces pin every input vertex.
  const std::uint32_t pinned = emb_points_.empty() ? 0 : fixed_count_;
  smooth_laplacian(m_, opt_.smoothing, resolve_thread_count(opt_.threads), pinned);
}

void FaceMesher::optimize() {
  if (opt_.smoothing <= 0 || !opt_.quality_pass) return;
  OptimizeOptions oo;
  if (opt_.algorithm == Mesh2dAlgorithm::Del2d || opt_.algorithm == Mesh2dAlgorithm::Automatic) {
    // del2d's many triangles just under 0.9 would cost ~4x the refinement to lift
    // (square: 87% -> 99% rho > 0.9); work on the bad ones only (~20% of refinement).
    oo.threshold = 0.75;
    oo.sacrifice_below = 0.7;
    oo.max_share_loss = 1e-4;
  }
  optimize_quality(m_, fixed_count_, oo);
}

Vec3 FaceMesher::space_of(VertexId v) const {
  if (v.value < global_.size() && global_[v.value] != kNoLocal) return mesh_.nodes[global_[v.value]].xyz;
  return plane_.to_space(m_.xy[v.value]);
}

int FaceMesher::curve_of(VertexId a, VertexId b) const {
  const auto it = edge_curve_of_.find(std::minmax(a.value, b.value));
  return it == edge_curve_of_.end() ? 0 : it->second;
}

void FaceMesher::raise_floor() {
  if (!(opt_.quality_floor > 0)) return;
  for (std::size_t i = 0; i < edges_.size(); ++i)
    edge_curve_of_[std::minmax(edges_[i].first.value, edges_[i].second.value)] = edge_curve_[i];
  std::vector<std::uint32_t> corners;   // global nodes of model vertices, sorted
  for (const auto& [vt, node] : mesh_.vertex_node) corners.push_back(node);
  std::sort(corners.begin(), corners.end());
  FloorFace face;
  face.space = [this](VertexId v) { return space_of(v); };
  face.to_space = [this](Vec2 p) { return plane_.to_space(p); };
  face.is_corner = [this, &corners](VertexId v) {
    return v.value < global_.size() && std::binary_search(corners.begin(), corners.end(), global_[v.value]);
  };
  face.curve_point = [this](VertexId a, VertexId b, double f) -> std::optional<Vec2> {
    const int c = curve_of(a, b);
    const geo::ModelCurve* mc = c > 0 ? model_.curve(c) : nullptr;
    const auto it = mesh_.curves.find(c);
    if (!mc || !mc->shape || it == mesh_.curves.end()) return std::nullopt;
    // A curve a face meshed before this one also holds stays as it is: that face's
    // triangle on the edge would have to be cut in two, unoptimised (a fan of slivers
    // after a few splits). Faces meshed later see the new nodes in the curve's 1D mesh.
    for (const auto& [st, sm] : mesh_.surfaces)
      if (st != tag_ && surface_uses_curve(model_, st, c)) return std::nullopt;
    const CurveMesh& cm = it->second;
    const std::uint32_t ga = global_[a.value], gb = global_[b.value];
    for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) {
      if (!((cm.nodes[k] == ga && cm.nodes[k + 1] == gb) || (cm.nodes[k] == gb && cm.nodes[k + 1] == ga))) continue;
      // On the curve itself, so the geometry does not change; f from the node of a.
      pending_.curve = c;
      pending_.k = k;
      const double fk = cm.nodes[k] == ga ? f : 1 - f;
      pending_.t = (1 - fk) * cm.t[k] + fk * cm.t[k + 1];
      const geo::Curve& shape = *mc->shape;
      pending_.node = shape.on_surface() ? MeshNode{shape.point(pending_.t), shape.eval_uv(pending_.t).p, true}
                                         : MeshNode{shape.point(pending_.t), {}, false};
      return plane_.node_plane(pending_.node);
    }
    return std::nullopt;
  };
  face.curve_split_done = [this](VertexId a, VertexId b, VertexId v) {
    mesh_.nodes.push_back(pending_.node);
    const std::uint32_t node = static_cast<std::uint32_t>(mesh_.nodes.size() - 1);
    CurveMesh& cm = mesh_.curves.at(pending_.curve);
    const auto at = static_cast<std::ptrdiff_t>(pending_.k + 1);
    cm.nodes.insert(cm.nodes.begin() + at, node);
    cm.t.insert(cm.t.begin() + at, pending_.t);
    floor_nodes_.emplace_back(pending_.curve, node);
    if (cm.h.size() > pending_.k + 1) cm.h.insert(cm.h.begin() + at, 0.5 * (cm.h[pending_.k] + cm.h[pending_.k + 1]));
    if (global_.size() <= v.value) global_.resize(v.value + 1, kNoLocal);
    global_[v.value] = node;
    edge_curve_of_.erase(std::minmax(a.value, b.value));
    edge_curve_of_[std::minmax(a.value, v.value)] = pending_.curve;
    edge_curve_of_[std::minmax(v.value, b.value)] = pending_.curve;
  };
  // First with transient losses allowed (a split may leave a triangle at half the one
  // worked on, for the next rounds to mend); if the face ends worse than it started (its
  // worst rho lower, or more triangles below q), everything is put back and the floor
  // runs again never going below the face's starting worst.
  const auto space = [this](VertexId v) { return space_of(v); };
  double worst_start = 1;
  const std::uint32_t below_start = count_below(m_, space, opt_.quality_floor, &worst_start);
  if (below_start == 0) return;
  const TriangleStore before = m_;
  const std::size_t nodes_start = mesh_.nodes.size(), global_start = global_.size();
  QualityFloorResult r, left;
  // Undo: the triangulation, the curve nodes (appended last, so the node array is cut
  // back) and the bookkeeping.
  const auto put_back = [&] {
    m_ = before;
    for (auto it = floor_nodes_.rbegin(); it != floor_nodes_.rend(); ++it) {
      CurveMesh& cm = mesh_.curves.at(it->first);
      const auto k = std::find(cm.nodes.begin(), cm.nodes.end(), it->second) - cm.nodes.begin();
      cm.nodes.erase(cm.nodes.begin() + k);
      cm.t.erase(cm.t.begin() + k);
      if (static_cast<std::size_t>(k) < cm.h.size()) cm.h.erase(cm.h.begin() + k);
    }
    floor_nodes_.clear();
    mesh_.nodes.resize(nodes_start);
    global_.resize(global_start);
    edge_curve_of_.clear();
    for (std::size_t i = 0; i < edges_.size(); ++i)
      edge_curve_of_[std::minmax(edges_[i].first.value, edges_[i].second.value)] = edge_curve_[i];
  };
  // An internal error of the floor (a walk that did not end: the triangulation is not
  // consistent there) puts the face back as it was before the floor, a valid mesh, and is
  // reported with its place.
  const auto faulted = [&](const QualityFloorResult& f) {
    if (f.fault.empty()) return false;
    const std::string at = where_text(space_of(f.fault_at));
    put_back();
    res_.quality_warnings.push_back(fmt::format(
        "surface {}: internal error: {} near {}; the face is left as it was before Mesh.QualityFloor", tag_, f.fault,
        at));
    return true;
  };
  // Above the floor that Ruppert's refinement can reach (its 20.7-degree angle bound,
  // rho 0.59: higher floors make sharp_angle_limit wider) the loss-allowing run cannot
  // converge and only spends its budget: the never-worse run alone.
  constexpr double kRefinementAngle = 20.7 * geo::kPi / 180;
  const bool beyond_refinement = sharp_angle_limit(opt_.quality_floor) > kRefinementAngle;
  bool worse = false;
  for (const bool never_worse : {false, true}) {
    if (!never_worse && beyond_refinement) continue;
    if (never_worse && !beyond_refinement) put_back();
    QualityFloorOptions fo;
    fo.floor = opt_.quality_floor;
    fo.never_below_start = never_worse;
    if (beyond_refinement) {
      // Most of what is below such a floor stays below it: a quarter of the budgets (one
      // point per triangle below it at the start), so that the run stays within about
      // twice the floor-off time (measured on the examples at 0.9).
      fo.max_points = below_start + 256;
      fo.max_work = 4 * std::uint64_t{below_start} + 64 * std::uint64_t(fo.max_rounds) + 1024;
    }
    r = raise_quality_floor(m_, face, fo);
    if (faulted(r)) return;
    if (r.changed() && opt_.smoothing > 0 && opt_.quality_pass) {
      // The quality pass again, on what the floor changed: only triangles below the floor
      // (and a margin) are worked on; the rest of the face was optimised already.
      OptimizeOptions oo;
      oo.threshold = std::min(0.9, opt_.quality_floor + 0.2);
      oo.sacrifice_below = oo.threshold;
      oo.compound_below = std::min(oo.threshold, opt_.quality_floor + 0.1);
      optimize_quality(m_, fixed_count_, oo);
    }
    // What is left, measured after the quality pass (no rounds: only the count).
    QualityFloorOptions count_only = fo;
    count_only.max_rounds = 0;
    left = raise_quality_floor(m_, face, count_only);
    if (faulted(left)) return;
    double worst_end = 1;
    count_below(m_, space, opt_.quality_floor, &worst_end);
    worse = r.changed() && !(worst_end >= worst_start && left.below_after <= below_start);
    if (!worse) break;
  }
  if (worse) {
    // Even the never-worse run (its quality pass may lose) left more triangles below the
    // floor, or a worse one, than the face started with: the face goes back as it was.
    const std::uint32_t ended = left.below_after;
    put_back();
    QualityFloorOptions count_only;
    count_only.floor = opt_.quality_floor;
    count_only.max_rounds = 0;
    left = raise_quality_floor(m_, face, count_only);
    if (faulted(left)) return;
    res_.quality_warnings.push_back(fmt::format(
        "surface {}: Mesh.QualityFloor = {:g} left {} triangles below it where the face had {} (after {} round{} and "
        "{} new points); the face is left as it was before the floor",
        tag_, opt_.quality_floor, ended, below_start, r.rounds, r.rounds == 1 ? "" : "s",
        r.curve_splits + r.interior_points));
    r = QualityFloorResult{};
  }
  res_.stats.floor_curve_splits += r.curve_splits;
  res_.stats.floor_points += r.interior_points;
  left.rounds = r.rounds, left.curve_splits = r.curve_splits, left.interior_points = r.interior_points;
  left.below_before = r.below_before;
  left.out_of_work = r.out_of_work, left.work = r.work, left.work_budget = r.work_budget;
  report_floor(left);
}

void FaceMesher::report_floor(const QualityFloorResult& r) {
  const double q = opt_.quality_floor;
  auto place = [this](VertexId v) { return where_text(space_of(v)); };
  if (!r.sharp.empty()) {
    constexpr std::size_t kListed = 8;
    std::string list;
    for (std::size_t i = 0; i < std::min(r.sharp.size(), kListed); ++i)
      list += fmt::format("{}{:.1f} degrees at {}", i ? "; " : "", r.sharp[i].degrees, place(r.sharp[i].v));
    if (r.sharp.size() > kListed) list += fmt::format("; and {} more", r.sharp.size() - kListed);
    res_.quality_warnings.push_back(fmt::format(
        "surface {}: {} triangle{} below Mesh.QualityFloor = {:g} where the boundary makes an angle too sharp for it "
        "(under {:.1f} degrees): {}",
        tag_, r.at_sharp, r.at_sharp == 1 ? "" : "s", q, sharp_angle_limit(q) * 180 / geo::kPi, list));
  }
  const std::uint32_t rest = r.below_after - r.at_sharp;
  if (rest > 0) {
    // The worst of them, for the place.
    double worst = 2;
    TriId wt;
    for (std::uint32_t t = 0; t < m_.num_slots(); ++t) {
      if (!m_.alive(TriId{t})) continue;
      const double rt = rho(space_of(m_.vertex(TriId{t}, 0)), space_of(m_.vertex(TriId{t}, 1)),
                            space_of(m_.vertex(TriId{t}, 2)));
      if (rt < worst) worst = rt, wt = TriId{t};
    }
    const Vec3 c = (space_of(m_.vertex(wt, 0)) + space_of(m_.vertex(wt, 1)) + space_of(m_.vertex(wt, 2))) / 3.0;
    res_.quality_warnings.push_back(fmt::format(
        "surface {}: {} triangle{} still below Mesh.QualityFloor = {:g} after {} round{} and {} new points (the work "
        "is bounded{}); the worst, rho {:.4f}, near {}",
        tag_, rest, rest == 1 ? "" : "s", q, r.rounds, r.rounds == 1 ? "" : "s", r.curve_splits + r.interior_points,
        r.out_of_work ? fmt::format(": its budget of {} operations ran out", r.work_budget) : std::string(), worst,
        where_text(c)));
  }
}

void FaceMesher::output() {
  SurfaceMesh sm_out;
  sm_out.tag = tag_;
  const std::uint32_t nv = m_.num_vertices();
  global_.resize(nv, kNoLocal);   // the floor's curve nodes have theirs already
  for (std::uint32_t v = fixed_count_; v < nv; ++v) {
    if (global_[v] != kNoLocal) continue;
    const Vec2 p = m_.xy[v];
    global_[v] = plane_.geom ? mesh_.add_node(plane_.to_space(p), plane_.to_param(p)) : mesh_.add_node(plane_.to_space(p));
    sm_out.interior_nodes.push_back(global_[v]);
  }
  const bool flip = plane_.geom && !plane_.ccw_is_outward;
  // Local triangles, counter-clockwise in the plane.
  std::vector<std::array<std::uint32_t, 3>> local;
  local.reserve(m_.num_triangles());
  for (std::uint32_t t = 0; t < m_.num_slots(); ++t) {
    if (!m_.alive(TriId{t})) continue;
    local.push_back({m_.vertex(TriId{t}, 0).value, m_.vertex(TriId{t}, 1).value, m_.vertex(TriId{t}, 2).value});
  }
  std::vector<std::array<std::uint32_t, 4>> local_quads;
  if (recombined()) {
    std::vector<Vec3> xyz(nv);
    for (std::uint32_t v = 0; v < nv; ++v) xyz[v] = mesh_.nodes[global_[v]].xyz;
    // Embedded curves stay edges of the mesh.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> fixed;
    for (const Chain& ch : emb_curves_)
      for (std::size_t k = 0; k + 1 < ch.nodes.size(); ++k)
        fixed.push_back(std::minmax(local_of_[ch.nodes[k]], local_of_[ch.nodes[k + 1]]));
    std::sort(fixed.begin(), fixed.end());
    RecombineOptions ro;
    ro.algorithm = opt_.constraints->algorithm;
    RecombineResult rr = recombine(local, xyz, m_.xy, fixed, ro);
    local = std::move(rr.triangles);
    local_quads = std::move(rr.quads);
  }
  append_elements(sm_out, local, local_quads, flip, [this](std::uint32_t v) { return global_[v]; });
  res_.stats.new_nodes += sm_out.interior_nodes.size();
  res_.stats.triangles += sm_out.triangles.size();
  res_.stats.quads += sm_out.quads.size();
  ++res_.stats.faces;
  mesh_.surfaces[tag_] = std::move(sm_out);
  res_.target_sizes.push_back({tag_, target_size_fn(sizing_)});
}

bool FaceMesher::run_transfinite(const geo::ModelSurface& s, const TransfiniteSurfaceSpec& spec) {
  if (!collect_loops(s)) return false;
  if (chains_.size() != 1) {
    const std::size_t holes = chains_.size() - 1;
    return fail(fmt::format("is transfinite but has {} hole{}", holes, holes == 1 ? "" : "s"));
  }
  const Chain& ch = chains_[0];
  const std::size_t n = ch.nodes.size();
  // A filling Surface has no plane: it is interpolated in space (onto its sphere when it
  // has one); a Plane Surface in its plane (a PolarSphere's stereographic plane).
  const bool in_plane = !s.filling;
  if (in_plane && !make_plane()) return false;
  TransfiniteBoundary b;
  b.coords.reserve(n), b.xyz.reserve(n);
  for (std::uint32_t node : ch.nodes) {
    const MeshNode& mn = mesh_.nodes[node];
    b.xyz.push_back(mn.xyz);
    if (in_plane) {
      const Vec2 p = plane_.node_plane(mn);
      b.coords.push_back({p.x, p.y, 0.0});
    } else {
      b.coords.push_back(mn.xyz);
    }
  }
  if (spec.corners.empty()) {
    std::vector<std::size_t> starts;
    for (std::size_t k = 0; k < n; ++k)
      if (k == 0 || ch.edge_curve[k] != ch.edge_curve[k - 1]) starts.push_back(k);
    b.corners = implicit_transfinite_corners(starts, n);
  } else {
    for (int corner : spec.corners) {
      const auto it = mesh_.vertex_node.find(corner);
      const auto at = it == mesh_.vertex_node.end() ? ch.nodes.end() : std::find(ch.nodes.begin(), ch.nodes.end(), it->second);
      if (at == ch.nodes.end())
        return fail(fmt::format("transfinite corner {} is not a point of its boundary", corner));
      b.corners.push_back(static_cast<std::size_t>(at - ch.nodes.begin()));
    }
  }
  const int smoothing = opt_.smoothing > 1 ? opt_.smoothing : 0;   // Gmsh: with Mesh.Smoothing > 1
  TransfiniteResult r = fill_transfinite(b, spec.arrangement, recombined(), smoothing);
  if (!r.ok()) return fail(r.error);
  std::optional<Vec3> centre;
  double radius = 0;
  if (s.filling && s.sphere_centre)
    if (const geo::ModelVertex* c = model_.vertex(s.sphere_centre)) centre = c->xyz, radius = norm(b.xyz[0] - c->xyz);
  SurfaceMesh out;
  out.tag = tag_;
  std::vector<std::uint32_t> id(ch.nodes.begin(), ch.nodes.end());
  for (const Vec3& p : r.interior) {
    std::uint32_t node;
    if (in_plane) {
      const Vec2 q{p.x, p.y};
      node = plane_.geom ? mesh_.add_node(plane_.to_space(q), plane_.to_param(q)) : mesh_.add_node(plane_.to_space(q));
    } else {
      Vec3 x = p;
      if (centre && norm(x - *centre) > 0) x = *centre + (radius / norm(x - *centre)) * (x - *centre);
      node = mesh_.add_node(x);
    }
    id.push_back(node);
    out.interior_nodes.push_back(node);
  }
  // Counter-clockwise in the plane: the elements run as the boundary chain does, which a
  // Euclidean plane's basis makes counter-clockwise; on a geometry the chain may turn
  // either way, so the elements' own majority decides. Then the orientation rule of
  // output(). A filling surface keeps its loop's orientation.
  bool flip = false;
  if (in_plane && plane_.geom) {
    long turn = 0;
    auto P = [&](std::uint32_t k) {
      return k < n ? Vec2{b.coords[k].x, b.coords[k].y} : Vec2{r.interior[k - n].x, r.interior[k - n].y};
    };
    for (const auto& t : r.triangles) turn += static_cast<int>(orient2d(P(t[0]), P(t[1]), P(t[2])));
    for (const auto& q : r.quads) turn += static_cast<int>(orient2d(P(q[0]), P(q[1]), P(q[2])));
    flip = (turn < 0) != !plane_.ccw_is_outward;
  }
  append_elements(out, r.triangles, r.quads, flip, [&id](std::uint32_t k) { return id[k]; });
  res_.stats.new_nodes += out.interior_nodes.size();
  res_.stats.triangles += out.triangles.size();
  res_.stats.quads += out.quads.size();
  ++res_.stats.faces;
  ++res_.stats.transfinite_faces;
  mesh_.surfaces[tag_] = std::move(out);
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
  const double bbox = model_bbox(model, opt.bbox_diag);
  std::vector<std::uint32_t> local_of;
  progress_begin(opt.progress, "2D", model.surfaces().size());
  std::uint64_t faces_done = 0;
  for (const auto& [tag, s] : model.surfaces()) {
    Mesh2dOptions own;   // a face with an algorithm of its own: the options with it
    const auto algo = opt.surface_algorithm.find(tag);
    if (algo != opt.surface_algorithm.end()) {
      own = opt;
      own.algorithm = algo->second;
    }
    FaceMesher fm(model, mesh, algo != opt.surface_algorithm.end() ? own : opt, bbox, res, local_of);
    if (!fm.run(s)) {
      progress_end(opt.progress);
      return res;
    }
    progress_update(opt.progress, ++faces_done);
  }
  progress_end(opt.progress);
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
    FaceMesher fm(model, mesh, opt, bbox, face, local_of);
    fm.estimate_only();
    if (!fm.run(s) && face.error.kind == MeshErrorKind::LimitExceeded) {
      res.error = face.error;
      return res;
    }
  }
  return res;
}

std::vector<StageTime> stage_times(const Mesh2dStats& s) {
  return {{"2D boundary", s.seconds_boundary},
          {"2D refine", s.seconds_refine},
          {"2D smooth", s.seconds_smooth},
          {"2D optimise", s.seconds_optimize},
          {"2D quality floor", s.seconds_floor},
          {"2D output", s.seconds_output}};
}

}  // namespace sm
