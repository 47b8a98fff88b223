// Structured-meshing statements into the kernel's mesh constraints (mesh/mesh_constraints.h)
// with Gmsh 4.8.4's meaning: `Transfinite Curve{c} = n Using Progression|Bump|Beta r;`,
// `Transfinite Surface{s} = {corners} Left|Right|Alternate...;`, `Recombine Surface{s};`.
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// Gmsh ignores constraints on entities that do not exist; we say so.
void report_missing(Interpreter& in, SourceRange at, const char* what, int tag) {
  in.diags().report(at, Diag::GmshCompat,
                    fmt::format("{} {} does not exist: Gmsh 4.8.4 ignores its mesh constraint, and so do we", what, tag));
}

void exec_transfinite_curve(Interpreter& in, const Stmt& s, const TransfiniteCurveStmt& n) {
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  TransfiniteCurveSpec spec;
  const double nodes = in.eval_number(n.nodes);
  if (!std::isfinite(nodes) || nodes > 1e8)
    in.fail_fmt(in.ast().expr(n.nodes).range, Diag::InvalidOperation,
                fmt::format("{:g} is not a number of nodes for a transfinite curve", nodes));
  spec.nodes = std::max(2, static_cast<int>(nodes));   // Gmsh: fewer than 2 is 2
  if (n.distribution.valid()) {
    const std::string_view law = in.ast().str(n.distribution);
    if (law == "Progression" || law == "Power") spec.law = TransfiniteLaw::Progression;
    else if (law == "Bump") spec.law = TransfiniteLaw::Bump;
    else if (law == "Beta") spec.law = TransfiniteLaw::Beta;
    else
      in.fail_fmt(s.range, Diag::InvalidOperation,
                  fmt::format("unknown transfinite law '{}': use Progression, Bump or Beta", law));
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
      in.fail_fmt(s.range, Diag::InvalidOperation,
                  fmt::format("unknown triangle arrangement '{}': use Left, Right, Alternate, AlternateRight or "
                              "AlternateLeft",
                              a));
  }
  if (n.corners.valid()) {
    spec.corners = eval_tags(in, n.corners);
    if (!spec.corners.empty() && spec.corners.size() != 3 && spec.corners.size() != 4)
      in.fail_fmt(in.ast().expr(n.corners).range, Diag::InvalidOperation,
                  fmt::format("a transfinite surface has 3 or 4 corners, not {}", spec.corners.size()));
    for (int& c : spec.corners) {
      c = std::abs(c);
      if (!m.vertex(c))
        in.fail_fmt(in.ast().expr(n.corners).range, Diag::InvalidOperation,
                    fmt::format("transfinite corner {} is not a point", c));
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
    in.fail_fmt(in.ast().expr(n.value).range, Diag::InvalidOperation,
                fmt::format("{:g} is not a mesh algorithm number", v));
  const std::vector<int> tags = n.all ? m.tags(2) : eval_tags(in, n.tags);
  for (int t : tags) {
    if (!m.surface(std::abs(t))) {
      report_missing(in, s.range, "surface", std::abs(t));
      continue;
    }
    k.constraints.surface_algorithm[std::abs(t)] = static_cast<int>(v);
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
    default: break;
  }
}

}  // namespace sm::interp
