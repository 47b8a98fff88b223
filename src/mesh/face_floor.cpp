// Step 7 of a face: the quality floor with the face's curves, corners and map to space,
// its undo when the face would end worse, and its report (face_floor.h).
#include "mesh/face_floor.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/parallel.h"
#include "exact/quality.h"
#include "mesh/modify/optimize.h"
#include "mesh/quality_floor.h"
#include "mesh/store_undo.h"

namespace sm {
namespace {

// The floor's curve splits while it runs: the curve of each boundary edge (local vertex
// pair, smaller first; embedded curves too), the split asked last, the nodes added.
struct FloorCurves {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_curve_of;
  struct PendingSplit {
    int curve = 0;
    std::size_t k = 0;  // between cm.nodes[k] and cm.nodes[k + 1]
    double t = 0;
    MeshNode node;
  } pending;
  std::vector<std::pair<int, std::uint32_t>> floor_nodes;  // (curve, node) the floor added
};

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

// The point in space of local vertex v: its node, or its plane point mapped.
Vec3 space_of(const FaceWork& f, VertexId v) {
  if (v.value < f.global.size() && f.global[v.value] != kNoLocal) return f.mesh.nodes[f.global[v.value]].xyz;
  return f.plane.to_space(f.tri.xy[v.value]);
}

// The curve of the face edge between local vertices a and b (0: none).
int curve_of(const FloorCurves& fl, VertexId a, VertexId b) {
  const auto it = fl.edge_curve_of.find(std::minmax(a.value, b.value));
  return it == fl.edge_curve_of.end() ? 0 : it->second;
}

// The floor's report: the triangles left at corners too sharp for it (with every such
// corner), then the rest with the place of the worst.
void report_floor(FaceWork& f, const QualityFloorResult& r) {
  const double q = f.opt.quality_floor;
  if (!r.sharp.empty()) {
    MeshNote note{.kind = MeshNoteKind::FloorSharpCorners,
                  .surface = f.tag,
                  .count = r.at_sharp,
                  .floor = q,
                  .sharp_limit_degrees = sharp_angle_limit(q) * 180 / geo::kPi};
    for (const SharpCorner& c : r.sharp) note.corners.push_back({c.degrees, f.place_of(space_of(f, c.v))});
    f.res.notes.push_back(std::move(note));
  }
  const std::uint32_t rest = r.below_after - r.at_sharp;
  if (rest > 0) {
    // The worst of them, for the place.
    const auto [wt, worst] =
        worst_triangle(f.tri, [&f](VertexId v) { return space_of(f, v); }, resolve_thread_count(f.opt.threads));
    const Vec3 c =
        (space_of(f, f.tri.vertex(wt, 0)) + space_of(f, f.tri.vertex(wt, 1)) + space_of(f, f.tri.vertex(wt, 2))) / 3.0;
    f.res.notes.push_back(MeshNote{.kind = MeshNoteKind::FloorStillBelow,
                                   .surface = f.tag,
                                   .place = f.place_of(c),
                                   .count = rest,
                                   .floor = q,
                                   .rounds = r.rounds,
                                   .new_points = std::uint64_t{r.curve_splits} + r.interior_points,
                                   .work_budget = r.out_of_work ? r.work_budget : 0,
                                   .worst_rho = worst});
  }
}

// Where the floor's split of boundary edge ab falls on its curve, `along` from a: the
// curve's own point (so the geometry does not change), kept pending until the split is
// done; none when the edge's curve must keep its nodes.
std::optional<Vec2> floor_curve_point(const FaceWork& f, FloorCurves& fl, VertexId a, VertexId b, double along) {
  const int c = curve_of(fl, a, b);
  const geo::ModelCurve* mc = c > 0 ? f.model.curve(c) : nullptr;
  const auto it = f.mesh.curves.find(c);
  if (!mc || !mc->shape || it == f.mesh.curves.end()) return std::nullopt;
  // A transfinite curve keeps the node count its script gave (Gmsh's meaning of
  // `Transfinite Curve{c} = n`: n nodes whatever the faces beside it become).
  if (f.opt.constraints && f.opt.constraints->curves.count(c)) return std::nullopt;
  // A curve a face meshed before this one also holds stays as it is: that face's
  // triangle on the edge would have to be cut in two, unoptimised (a fan of slivers
  // after a few splits). Faces meshed later see the new nodes in the curve's 1D mesh.
  for (const auto& [st, sm] : f.mesh.surfaces)
    if (st != f.tag && surface_uses_curve(f.model, st, c)) return std::nullopt;
  const CurveMesh& cm = it->second;
  const std::uint32_t ga = f.global[a.value], gb = f.global[b.value];
  for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) {
    if (!((cm.nodes[k] == ga && cm.nodes[k + 1] == gb) || (cm.nodes[k] == gb && cm.nodes[k + 1] == ga))) continue;
    fl.pending.curve = c;
    fl.pending.k = k;
    const double fk = cm.nodes[k] == ga ? along : 1 - along;
    fl.pending.t = (1 - fk) * cm.t[k] + fk * cm.t[k + 1];
    const geo::Curve& shape = *mc->shape;
    fl.pending.node = shape.on_surface() ? MeshNode{shape.point(fl.pending.t), shape.eval_uv(fl.pending.t).p, true}
                                         : MeshNode{shape.point(fl.pending.t), {}, false};
    return f.plane.node_plane(fl.pending.node);
  }
  return std::nullopt;
}

// The pending split done as local vertex v between a and b: its node into the mesh and
// into its curve's 1D mesh, and the two halves' curve recorded.
void record_curve_split(FaceWork& f, FloorCurves& fl, VertexId a, VertexId b, VertexId v) {
  f.mesh.nodes.push_back(fl.pending.node);
  const std::uint32_t node = static_cast<std::uint32_t>(f.mesh.nodes.size() - 1);
  CurveMesh& cm = f.mesh.curves.at(fl.pending.curve);
  const auto at = static_cast<std::ptrdiff_t>(fl.pending.k + 1);
  cm.nodes.insert(cm.nodes.begin() + at, node);
  cm.t.insert(cm.t.begin() + at, fl.pending.t);
  fl.floor_nodes.emplace_back(fl.pending.curve, node);
  if (cm.h.size() > fl.pending.k + 1)
    cm.h.insert(cm.h.begin() + at, 0.5 * (cm.h[fl.pending.k] + cm.h[fl.pending.k + 1]));
  if (f.global.size() <= v.value) f.global.resize(v.value + 1, kNoLocal);
  f.global[v.value] = node;
  fl.edge_curve_of.erase(std::minmax(a.value, b.value));
  fl.edge_curve_of[std::minmax(a.value, v.value)] = fl.pending.curve;
  fl.edge_curve_of[std::minmax(v.value, b.value)] = fl.pending.curve;
}

// The face as the floor sees it: its map to space, its corners (`corners`: the global
// nodes of model vertices, sorted) and its curves to split.
FloorFace floor_face(FaceWork& f, FloorCurves& fl, const std::vector<std::uint32_t>& corners) {
  FloorFace face;
  face.space = [&f](VertexId v) { return space_of(f, v); };
  face.to_space = [&f](Vec2 p) { return f.plane.to_space(p); };
  face.is_corner = [&f, &corners](VertexId v) {
    return v.value < f.global.size() && std::binary_search(corners.begin(), corners.end(), f.global[v.value]);
  };
  face.curve_point = [&f, &fl](VertexId a, VertexId b, double along) { return floor_curve_point(f, fl, a, b, along); };
  face.curve_split_done = [&f, &fl](VertexId a, VertexId b, VertexId v) { record_curve_split(f, fl, a, b, v); };
  return face;
}

void set_edge_curves(const FaceWork& f, FloorCurves& fl) {
  fl.edge_curve_of.clear();
  for (std::size_t i = 0; i < f.edges.size(); ++i)
    fl.edge_curve_of[std::minmax(f.edges[i].first.value, f.edges[i].second.value)] = f.edge_curve[i];
}

// What the floor and its quality pass change, journalled to be put back (store_undo.h: a
// copy of the whole store here was 40 bytes a triangle at the 2D peak): the
// triangulation, the curve nodes (appended last, so the node array is cut back) and the
// bookkeeping.
class FloorUndo {
 public:
  FloorUndo(FaceWork& f, FloorCurves& fl)
      : f_(f), fl_(fl), before_(f.tri), nodes_start_(f.mesh.nodes.size()), global_start_(f.global.size()) {}

  void put_back() {
    before_.restore(f_.tri);
    for (auto it = fl_.floor_nodes.rbegin(); it != fl_.floor_nodes.rend(); ++it) {
      CurveMesh& cm = f_.mesh.curves.at(it->first);
      const auto k = std::find(cm.nodes.begin(), cm.nodes.end(), it->second) - cm.nodes.begin();
      cm.nodes.erase(cm.nodes.begin() + k);
      cm.t.erase(cm.t.begin() + k);
      if (static_cast<std::size_t>(k) < cm.h.size()) cm.h.erase(cm.h.begin() + k);
    }
    fl_.floor_nodes.clear();
    f_.mesh.nodes.resize(nodes_start_);
    f_.global.resize(global_start_);
    set_edge_curves(f_, fl_);
  }

  // An internal error of the floor (a walk that did not end: the triangulation is not
  // consistent there) puts the face back as it was before the floor, a valid mesh, and is
  // reported with its place.
  bool faulted(const QualityFloorResult& q) {
    if (q.fault.empty()) return false;
    const MeshPlace at = f_.place_of(space_of(f_, q.fault_at));
    put_back();
    f_.res.notes.push_back(
        MeshNote{.kind = MeshNoteKind::FloorFault, .surface = f_.tag, .place = at, .fault = q.fault});
    return true;
  }

 private:
  FaceWork& f_;
  FloorCurves& fl_;
  StoreUndo before_;
  std::size_t nodes_start_, global_start_;
};

// The floor's options for one run: losses allowed or never below the face's start, and,
// above the floor refinement can reach, the smaller budgets.
QualityFloorOptions floor_run_options(const FaceWork& f, bool never_worse, bool beyond_refinement,
                                      std::uint32_t below_start) {
  QualityFloorOptions fo;
  fo.floor = f.opt.quality_floor;
  fo.never_below_start = never_worse;
  fo.threads = resolve_thread_count(f.opt.threads);
  if (beyond_refinement) {
    // Most of what is below such a floor stays below it: a quarter of the budgets (one
    // point per triangle below it at the start), so that the run stays within about
    // twice the floor-off time (measured on the examples at 0.9).
    fo.max_points = below_start + 256;
    fo.max_work = 4 * std::uint64_t{below_start} + 64 * std::uint64_t(fo.max_rounds) + 1024;
  }
  return fo;
}

// The quality pass again, on what the floor changed: only triangles below the floor (and
// a margin) are worked on; the rest of the face was optimised already.
void requality_after_floor(FaceWork& f) {
  OptimizeOptions oo;
  oo.threshold = std::min(0.9, f.opt.quality_floor + 0.2);
  oo.sacrifice_below = oo.threshold;
  oo.compound_below = std::min(oo.threshold, f.opt.quality_floor + 0.1);
  oo.threads = resolve_thread_count(f.opt.threads);
  optimize_quality(f.tri, f.fixed_count, oo);
}

}  // namespace

void raise_face_floor(FaceWork& f) {
  // Not with boundary layers: the floor splits boundary edges, the layers' among them.
  if (!(f.opt.quality_floor > 0) || f.has_layers()) return;
  FloorCurves fl;
  set_edge_curves(f, fl);
  std::vector<std::uint32_t> corners;  // global nodes of model vertices, sorted
  for (const auto& [vt, node] : f.mesh.vertex_node) corners.push_back(node);
  std::sort(corners.begin(), corners.end());
  const FloorFace face = floor_face(f, fl, corners);
  // First with transient losses allowed (a split may leave a triangle at half the one
  // worked on, for the next rounds to mend); if the face ends worse than it started (its
  // worst rho lower, or more triangles below q), everything is put back and the floor
  // runs again never going below the face's starting worst.
  const auto space = [&f](VertexId v) { return space_of(f, v); };
  double worst_start = 1;
  const int threads = resolve_thread_count(f.opt.threads);
  const std::uint32_t below_start = count_below(f.tri, space, f.opt.quality_floor, &worst_start, threads);
  if (below_start == 0) return;
  // The refinement's merge sized the store's arrays exactly (partition.cpp): room for
  // the floor's points (at most QualityFloorOptions' default budget, each 2 triangles net,
  // the insertion reusing the dead slots), else its first new triangle doubles every
  // array of the store, a copy of it held beside the old one (the world at 10 km: 58 MiB
  // more resident). Capacity only: the mesh is the same.
  // Never more than the store's own size (what doubling would have added).
  const auto room = static_cast<std::uint32_t>(
      std::min<std::uint64_t>(4 * std::uint64_t{below_start} + 256 + 1024, f.tri.num_slots()));
  f.tri.reserve(f.tri.num_vertices() + room, f.tri.num_slots() + 2 * room);
  FloorUndo undo(f, fl);
  QualityFloorResult r, left;
  // Above the floor that Ruppert's refinement can reach (its 20.7-degree angle bound,
  // rho 0.59: higher floors make sharp_angle_limit wider) the loss-allowing run cannot
  // converge and only spends its budget: the never-worse run alone.
  constexpr double kRefinementAngle = 20.7 * geo::kPi / 180;
  const bool beyond_refinement = sharp_angle_limit(f.opt.quality_floor) > kRefinementAngle;
  bool worse = false;
  for (const bool never_worse : {false, true}) {
    if (!never_worse && beyond_refinement) continue;
    if (never_worse && !beyond_refinement) undo.put_back();
    const QualityFloorOptions fo = floor_run_options(f, never_worse, beyond_refinement, below_start);
    r = raise_quality_floor(f.tri, face, fo);
    if (undo.faulted(r)) return;
    if (r.changed() && f.opt.smoothing > 0 && f.opt.quality_pass) requality_after_floor(f);
    // What is left, measured after the quality pass (no rounds: only the count, and the
    // worst rho from the same scan: count_below's answer).
    QualityFloorOptions count_only = fo;
    count_only.max_rounds = 0;
    left = raise_quality_floor(f.tri, face, count_only);
    if (undo.faulted(left)) return;
    const double worst_end = left.worst_before;
    worse = r.changed() && !(worst_end >= worst_start && left.below_after <= below_start);
    if (!worse) break;
  }
  if (worse) {
    // Even the never-worse run (its quality pass may lose) left more triangles below the
    // floor, or a worse one, than the face started with: the face goes back as it was.
    const std::uint32_t ended = left.below_after;
    undo.put_back();
    QualityFloorOptions count_only;
    count_only.floor = f.opt.quality_floor;
    count_only.max_rounds = 0;
    count_only.threads = threads;
    left = raise_quality_floor(f.tri, face, count_only);
    if (undo.faulted(left)) return;
    f.res.notes.push_back(MeshNote{.kind = MeshNoteKind::FloorPutBack,
                                   .surface = f.tag,
                                   .count = ended,
                                   .count_before = below_start,
                                   .floor = f.opt.quality_floor,
                                   .rounds = r.rounds,
                                   .new_points = std::uint64_t{r.curve_splits} + r.interior_points});
    r = QualityFloorResult{};
  }
  f.res.stats.floor_curve_splits += r.curve_splits;
  f.res.stats.floor_points += r.interior_points;
  left.rounds = r.rounds, left.curve_splits = r.curve_splits, left.interior_points = r.interior_points;
  left.below_before = r.below_before;
  left.out_of_work = r.out_of_work, left.work = r.work, left.work_budget = r.work_budget;
  report_floor(f, left);
}

}  // namespace sm
