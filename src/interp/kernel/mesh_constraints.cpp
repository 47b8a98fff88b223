// Structured-meshing statements into the kernel's mesh constraints (mesh/mesh_constraints.h)
// with Gmsh 4.8.4's meaning: `Transfinite Curve{c} = n Using Progression|Bump|Beta r;`,
// `Transfinite Surface{s} = {corners} Left|Right|Alternate...;`, `Recombine Surface{s};`.
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "mesh/periodic_curve.h"
#include "mesh/periodic_surface.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// Gmsh ignores constraints on entities that do not exist; we say so.
void report_missing(Interpreter& in, SourceRange at, const char* what, int tag) {
  in.diags().report(at, Diag::GmshCompatConstraintMissing, what, tag);
}

void exec_transfinite_curve(Interpreter& in, const Stmt& s, const TransfiniteCurveStmt& n) {
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  TransfiniteCurveSpec spec;
  const double nodes = in.eval_number(n.nodes);
  if (!std::isfinite(nodes) || nodes > 1e8)
    in.fail(in.ast().expr(n.nodes).range, Diag::TransfiniteNodeCount, nodes);
  spec.nodes = std::max(2, static_cast<int>(nodes));   // Gmsh: fewer than 2 is 2
  if (n.distribution.valid()) {
    const std::string_view law = in.ast().str(n.distribution);
    if (law == "Progression" || law == "Power") spec.law = TransfiniteLaw::Progression;
    else if (law == "Bump") spec.law = TransfiniteLaw::Bump;
    else if (law == "Beta") spec.law = TransfiniteLaw::Beta;
    else
      in.fail(s.range, Diag::UnknownTransfiniteLaw, law);
    spec.coef = std::fabs(in.eval_number(n.coef));   // Gmsh takes |coef|: a sign reverses nothing
  }
  const std::vector<int> tags = n.all ? m.tags(1) : eval_tags(in, n.curves);
  for (int t : tags) {
    if (!m.curve(std::abs(t))) {
      report_missing(in, s.range, "curve", std::abs(t));
      continue;
    }
    TransfiniteCurveSpec c = spec;
    c.reversed = t < 0;   // Gmsh: the law of curve -c runs from c's end
    k.constraints.curves[std::abs(t)] = c;
  }
}

void exec_transfinite_surface(Interpreter& in, const Stmt& s, const TransfiniteSurfaceStmt& n) {
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  TransfiniteSurfaceSpec spec;
  if (n.arrangement.valid()) {
    const std::string_view a = in.ast().str(n.arrangement);
    if (a == "Left") spec.arrangement = TriangleArrangement::Left;
    else if (a == "Right") spec.arrangement = TriangleArrangement::Right;
    else if (a == "Alternate" || a == "AlternateRight") spec.arrangement = TriangleArrangement::AlternateRight;
    else if (a == "AlternateLeft") spec.arrangement = TriangleArrangement::AlternateLeft;
    else
      in.fail(s.range, Diag::UnknownTriangleArrangement, a);
  }
  if (n.corners.valid()) {
    spec.corners = eval_tags(in, n.corners);
    if (!spec.corners.empty() && spec.corners.size() != 3 && spec.corners.size() != 4)
      in.fail(in.ast().expr(n.corners).range, Diag::TransfiniteCornerCount, spec.corners.size());
    for (int& c : spec.corners) {
      c = std::abs(c);
      if (!m.vertex(c))
        in.fail(in.ast().expr(n.corners).range, Diag::TransfiniteCornerNotPoint, c);
    }
  }
  const std::vector<int> tags = n.all ? m.tags(2) : eval_tags(in, n.surfaces);
  for (int t : tags) {
    if (!m.surface(std::abs(t))) {
      report_missing(in, s.range, "surface", std::abs(t));
      continue;
    }
    k.constraints.surfaces[std::abs(t)] = spec;
  }
}

void exec_recombine(Interpreter& in, StmtId id, const Stmt& s, const RecombineStmt& n) {
  if (n.ent != EntityKind::Surface) {
    in.not_supported_stmt(id, "Recombine Volume");
    return;
  }
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  // The angle (Gmsh's recombineAngle) only bounds its simple pass, which its own quality
  // measure never reaches: evaluated for errors, not used.
  if (n.angle.valid()) in.eval_number(n.angle);
  const std::vector<int> tags = n.all ? m.tags(2) : eval_tags(in, n.tags);
  for (int t : tags) {
    if (!m.surface(std::abs(t))) {
      report_missing(in, s.range, "surface", std::abs(t));
      continue;
    }
    k.constraints.recombine.insert(std::abs(t));
  }
}

// `MeshAlgorithm Surface{s} = n;` (Gmsh's meshAttributes.algorithm of those surfaces; the
// number is checked when meshing, as Mesh.Algorithm is). The other settings (Smoother,
// MeshSizeFromBoundary) and other entity kinds are not supported yet.
void exec_entity_setting(Interpreter& in, StmtId id, const Stmt& s, const EntitySettingStmt& n) {
  if (n.kind != SettingKind::MeshAlgorithm || n.ent != EntityKind::Surface) {
    exec_geometry_stmt(in, id);
    return;
  }
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  const double v = in.eval_number(n.value);
  if (!std::isfinite(v) || std::fabs(v) > 1e6)
    in.fail(in.ast().expr(n.value).range, Diag::NotMeshAlgorithm, v);
  const std::vector<int> tags = n.all ? m.tags(2) : eval_tags(in, n.tags);
  for (int t : tags) {
    if (!m.surface(std::abs(t))) {
      report_missing(in, s.range, "surface", std::abs(t));
      continue;
    }
    k.constraints.surface_algorithm[std::abs(t)] = static_cast<int>(v);
  }
}

// The 16 numbers of a `Periodic Curve` statement's transform (empty without one).
std::vector<double> periodic_affine(Interpreter& in, const Stmt& s, const PeriodicStmt& n) {
  std::vector<std::vector<double>> items;
  std::vector<double> all;
  for (ExprId e : n.transform_args) {
    items.push_back(in.eval_numbers(e));
    all.insert(all.end(), items.back().begin(), items.back().end());
  }
  // The kind names the form the transform takes; its argument is the count found.
  auto bad = [&](DiagFormat<std::size_t> form) { in.fail(s.range, form, all.size()); };
  switch (n.transform) {
    case PeriodicTransform::None: return {};
    case PeriodicTransform::Translate:
      if (all.size() != 3) bad(Diag::PeriodicTranslateArguments);
      return periodic_translation({all[0], all[1], all[2]});
    case PeriodicTransform::Rotate: {
      if (items.size() != 3 || items[0].size() != 3 || items[1].size() != 3 || items[2].size() != 1)
        bad(Diag::PeriodicRotateArguments);
      std::vector<double> a = periodic_rotation({items[0][0], items[0][1], items[0][2]},
                                                {items[1][0], items[1][1], items[1][2]}, items[2][0]);
      if (a.empty()) in.fail(s.range, Diag::PeriodicAxisZero);
      return a;
    }
    case PeriodicTransform::Affine:
      // Gmsh reads the first 12 (the matrix's three rows); the last row is 0 0 0 1.
      if (all.size() != 12 && all.size() != 16) bad(Diag::PeriodicAffineArguments);
      all.resize(12);
      all.insert(all.end(), {0, 0, 0, 1});
      return all;
  }
  return {};
}

// `Periodic Curve{targets} = {sources} [Translate{..} | Rotate{..} | Affine{..}];`
// (Gmsh 4.8.4's addPeriodicEdge): each target's mesh becomes a copy of its source's.
// Without a transform the signs give the direction; with one, the transform must take
// the source's end points onto the target's (within Geometry.Tolerance of the model's
// size, as Gmsh 4.8.4 checks it), which gives the direction.
// Curve `t`'s mesh a copy of curve `spec.source`'s, and the nodes of t's end points copies
// of their masters' (for a surface's curves, a point that maps onto itself, on a rotation's
// axis, is left out as Gmsh leaves it).
void add_periodic_curve(KernelState& k, int t, PeriodicCurveSpec spec, bool skip_fixed_points) {
  const geo::Model& m = k.model;
  const geo::ModelCurve& tc = *m.curve(t);
  const geo::ModelCurve& sc = *m.curve(spec.source);
  const int master_of_begin = spec.orientation > 0 ? sc.begin : sc.end;
  const int master_of_end = spec.orientation > 0 ? sc.end : sc.begin;
  if (!skip_fixed_points || tc.begin != master_of_begin)
    k.constraints.periodic_points[tc.begin] = {master_of_begin, spec.affine};
  if (!skip_fixed_points || tc.end != master_of_end)
    k.constraints.periodic_points[tc.end] = {master_of_end, spec.affine};
  k.constraints.periodic_curves[t] = std::move(spec);
}

void exec_periodic_curve(Interpreter& in, const Stmt& s, const PeriodicStmt& n) {
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  const std::vector<int> targets = eval_tags(in, n.slaves), sources = eval_tags(in, n.masters);
  if (targets.size() != sources.size())
    in.fail(s.range, Diag::PeriodicCurveCounts, targets.size(), sources.size());
  const std::vector<double> affine = periodic_affine(in, s, n);
  const double tolerance = m.options().tolerance * m.bounding_box().diagonal();
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const int t = std::abs(targets[i]), src = std::abs(sources[i]);
    for (int c : {t, src})
      if (!m.curve(c))
        in.fail(s.range, Diag::PeriodicCurveMissing, t, c);
    if (t == src)
      in.fail(s.range, Diag::PeriodicCurveItself, t);
    PeriodicCurveSpec spec{src, (targets[i] < 0) != (sources[i] < 0) ? -1 : 1, affine};
    if (!affine.empty()) {
      std::pair<double, double> d{0, 0};
      const std::optional<int> o = periodic_orientation(m, t, src, affine, tolerance, &d);
      if (!o)
        in.fail(s.range, Diag::PeriodicEndsMissed, src, t, d.first, d.second, tolerance);
      spec.orientation = *o;
    }
    add_periodic_curve(k, t, std::move(spec), false);
  }
}

// The curves bounding surface `tag` (unsigned).
std::set<int> surface_curves(const geo::Model& m, int tag) {
  std::set<int> out;
  for (int l : m.surface(tag)->loops)
    if (const geo::ModelCurveLoop* loop = m.curve_loop(std::abs(l)))
      for (int c : loop->curves) out.insert(std::abs(c));
  return out;
}

// The end points of the paired curves, master's point -> target's point (Gmsh's pairing in
// GFace::setMeshMaster: the signs of a pair say whether the curves run alike).
std::map<int, int> paired_points(const geo::Model& m, const std::vector<int>& targets,
                                 const std::vector<int>& sources) {
  std::map<int, int> out;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const geo::ModelCurve& tc = *m.curve(std::abs(targets[i]));
    const geo::ModelCurve& sc = *m.curve(std::abs(sources[i]));
    const bool alike = (targets[i] < 0) == (sources[i] < 0);
    out[sc.begin] = alike ? tc.begin : tc.end;
    out[sc.end] = alike ? tc.end : tc.begin;
  }
  return out;
}

// Surface t copying surface src must not close a circle of copies (t is src's source, or
// its source's...): each step follows one recorded copy, so at most that many steps.
void check_no_copy_cycle(Interpreter& in, const Stmt& s, int t, int src) {
  const std::map<int, PeriodicSurfaceSpec>& copies = in.kernel().constraints.periodic_surfaces;
  for (int cur = src, steps = 0; steps <= static_cast<int>(copies.size()); ++steps) {
    const auto up = copies.find(cur);
    if (up == copies.end()) break;
    if (up->second.source == t) in.fail(s.range, Diag::PeriodicSurfaceCycle, t, src, t);
    cur = up->second.source;
  }
}

// A failed pairing of surface t's points and curves with src's, at the list it concerns.
void report_match_miss(Interpreter& in, const Stmt& s, const PeriodicStmt& n, const PeriodicSurfaceMatch& match,
                       int t, int src, double tolerance) {
  using Miss = PeriodicSurfaceMatch::Miss;
  const SourceRange targets = in.ast().expr(n.slaves).range, sources = in.ast().expr(n.masters).range;
  switch (match.miss) {
    case Miss::None: return;
    case Miss::Counts:
      in.fail(s.range, Diag::PeriodicSurfaceEntityCounts,
              n.slave_surface.valid() ? "embedded points and curves (with the curves' end points)"
                                      : "points and curves, boundary and embedded",
              t, match.counts[0], match.counts[1], src, match.counts[2], match.counts[3]);
    case Miss::Point:
      in.fail(sources, Diag::PeriodicSurfacePointUnmatched, match.entity, src, match.image.x, match.image.y,
              match.image.z, t, match.distance, tolerance);
    case Miss::Curve: in.fail(targets, Diag::PeriodicSurfaceCurveUnmatched, match.entity, t, src);
  }
}

// Surface t's mesh a copy of spec.source's: each paired curve becomes periodic (Gmsh: a
// curve that maps onto itself, a rotation's axis, keeps its own mesh).
void record_periodic_surface(KernelState& k, int t, PeriodicSurfaceSpec spec) {
  for (const PeriodicSurfaceSpec::CurvePair& p : spec.curves)
    if (p.target != p.source) add_periodic_curve(k, p.target, {p.source, p.orientation, spec.affine}, true);
  k.constraints.periodic_surfaces[t] = std::move(spec);
}

// `Periodic Surface target {curves} = source {curves};` (Gmsh 4.8.4's addPeriodicFace): the
// target's mesh becomes a copy of the source's, by the translation or rotation that takes
// the paired curves' end points onto each other; each pair of curves becomes periodic (a
// curve paired with itself, on a rotation's axis, stays as it is).
void exec_periodic_surface(Interpreter& in, const Stmt& s, const PeriodicStmt& n) {
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  const int t = static_cast<int>(in.eval_number(n.slave_surface));
  const int src = static_cast<int>(in.eval_number(n.master_surface));
  const std::vector<int> targets = eval_tags(in, n.slaves), sources = eval_tags(in, n.masters);
  for (int f : {t, src})
    if (!m.surface(f)) in.fail(s.range, Diag::PeriodicSurfaceMissing, t, f);
  if (t == src) in.fail(s.range, Diag::PeriodicSurfaceItself, t);
  if (targets.size() != sources.size())
    in.fail(s.range, Diag::PeriodicSurfaceCurveCounts, targets.size(), t, sources.size(), src);
  const std::set<int> target_boundary = surface_curves(m, t), source_boundary = surface_curves(m, src);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    for (int c : {targets[i], sources[i]})
      if (!m.curve(std::abs(c))) in.fail(s.range, Diag::PeriodicCurveMissing, std::abs(targets[i]), std::abs(c));
    if (!target_boundary.count(std::abs(targets[i])))
      in.fail(in.ast().expr(n.slaves).range, Diag::PeriodicSurfaceCurveOff, std::abs(targets[i]), t);
    if (!source_boundary.count(std::abs(sources[i])))
      in.fail(in.ast().expr(n.masters).range, Diag::PeriodicSurfaceCurveOff, std::abs(sources[i]), src);
  }
  std::set<int> listed;
  for (int c : targets) listed.insert(std::abs(c));
  for (int c : target_boundary)
    if (!listed.count(c)) in.fail(in.ast().expr(n.slaves).range, Diag::PeriodicSurfaceCurveUnpaired, c, t);
  check_no_copy_cycle(in, s, t, src);

  const double tolerance = m.options().tolerance * m.bounding_box().diagonal();
  const std::map<int, int> points = paired_points(m, targets, sources);
  std::vector<std::pair<Vec3, Vec3>> places;
  for (const auto& [from, to] : points) places.emplace_back(m.vertex(from)->xyz, m.vertex(to)->xyz);
  std::string why;
  const std::vector<double> affine = infer_periodic_transform(places, tolerance, &why);
  if (affine.empty()) in.fail(s.range, Diag::PeriodicSurfaceNoMap, t, src, why);
  for (const auto& [from, to] : points) {
    const double miss = norm(apply_affine(affine, m.vertex(from)->xyz) - m.vertex(to)->xyz);
    if (!(miss <= tolerance)) in.fail(s.range, Diag::PeriodicSurfacePointMissed, from, to, miss, tolerance);
  }
  PeriodicSurfaceSpec spec{src, affine, {}, {}};
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const int tc = std::abs(targets[i]), sc = std::abs(sources[i]);
    std::pair<double, double> d{0, 0};
    const std::optional<int> o = periodic_orientation(m, tc, sc, affine, tolerance, &d);
    if (!o) in.fail(s.range, Diag::PeriodicEndsMissed, sc, tc, d.first, d.second, tolerance);
    spec.curves.push_back({tc, sc, *o});
  }
  // Gmsh pairs the embedded points and curves by the map found (its setMeshMaster with a
  // transform, which the curve-list form ends in): the copy carries them over.
  const PeriodicSurfaceMatch embedded = match_periodic_surface(m, t, src, affine, tolerance, true);
  report_match_miss(in, s, n, embedded, t, src, tolerance);
  spec.curves.insert(spec.curves.end(), embedded.curves.begin(), embedded.curves.end());
  spec.points = embedded.points;
  record_periodic_surface(k, t, std::move(spec));
}

// `Periodic Surface{targets} = {sources} Translate{..} | Rotate{..} | Affine{..};` (Gmsh
// 4.8.4's addPeriodicFace with a transform): each target's mesh becomes a copy of its
// source's, the points and curves (boundary and embedded) paired by where the map takes
// the source's. Gmsh refuses the form without a transform; so do we.
void exec_periodic_surfaces_by_map(Interpreter& in, const Stmt& s, const PeriodicStmt& n) {
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  const std::vector<int> targets = eval_tags(in, n.slaves), sources = eval_tags(in, n.masters);
  if (targets.size() != sources.size()) in.fail(s.range, Diag::PeriodicSurfaceCounts, targets.size(), sources.size());
  if (n.transform == PeriodicTransform::None) in.fail(s.range, Diag::PeriodicSurfaceNeedsTransform);
  const std::vector<double> affine = periodic_affine(in, s, n);
  const double tolerance = m.options().tolerance * m.bounding_box().diagonal();
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const int t = std::abs(targets[i]), src = std::abs(sources[i]);
    for (int f : {t, src})
      if (!m.surface(f)) in.fail(s.range, Diag::PeriodicSurfaceMissing, t, f);
    if (t == src) in.fail(s.range, Diag::PeriodicSurfaceItself, t);
    check_no_copy_cycle(in, s, t, src);
    const PeriodicSurfaceMatch match = match_periodic_surface(m, t, src, affine, tolerance, false);
    report_match_miss(in, s, n, match, t, src, tolerance);
    record_periodic_surface(k, t, {src, affine, match.curves, match.points});
  }
}

}  // namespace

void exec_mesh_constraint_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  switch (s.kind()) {
    case StmtKind::TransfiniteCurve: exec_transfinite_curve(in, s, std::get<TransfiniteCurveStmt>(s.node)); break;
    case StmtKind::TransfiniteSurface: exec_transfinite_surface(in, s, std::get<TransfiniteSurfaceStmt>(s.node)); break;
    case StmtKind::Recombine: exec_recombine(in, id, s, std::get<RecombineStmt>(s.node)); break;
    case StmtKind::EntitySetting: exec_entity_setting(in, id, s, std::get<EntitySettingStmt>(s.node)); break;
    case StmtKind::Periodic: {
      const auto& n = std::get<PeriodicStmt>(s.node);
      if (n.slave_surface.valid()) exec_periodic_surface(in, s, n);
      else if (n.ent == EntityKind::Curve) exec_periodic_curve(in, s, n);
      else if (n.ent == EntityKind::Surface) exec_periodic_surfaces_by_map(in, s, n);
      else exec_geometry_stmt(in, id);
      break;
    }
    default: break;
  }
}

}  // namespace sm::interp
