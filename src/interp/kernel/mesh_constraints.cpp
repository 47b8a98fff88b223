// Structured-meshing statements into the kernel's mesh constraints (mesh/mesh_constraints.h)
// with Gmsh 4.8.4's meaning: `Transfinite Curve{c} = n Using Progression|Bump|Beta r;`,
// `Transfinite Surface{s} = {corners} Left|Right|Alternate...;`, `Recombine Surface{s};`.
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "mesh/periodic_curve.h"

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
    const geo::ModelCurve& tc = *m.curve(t);
    const geo::ModelCurve& sc = *m.curve(src);
    k.constraints.periodic_points[tc.begin] = {spec.orientation > 0 ? sc.begin : sc.end, affine};
    k.constraints.periodic_points[tc.end] = {spec.orientation > 0 ? sc.end : sc.begin, affine};
    k.constraints.periodic_curves[t] = std::move(spec);
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
      // `Periodic Surface` (a copy of a surface's mesh) is not supported yet: reported as such.
      if (n.ent == EntityKind::Curve && !n.slave_surface.valid()) exec_periodic_curve(in, s, n);
      else exec_geometry_stmt(in, id);
      break;
    }
    default: break;
  }
}

}  // namespace sm::interp
