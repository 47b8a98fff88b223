// Geometry statements evaluated into the kernel's model (geo::Model) with Gmsh 4.8.4's
// meaning (docs/geometry.md), new* tags, and the statements the kernel has no
// place for yet (reported 'not supported yet', never dropped silently).
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "interp/kernel/compound.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/geo_diagnostic.h"
#include "interp/interpreter.h"
#include "interp/provenance.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// The statement's keyword(s) as written ("Line Loop", "Plane Surface").
std::string stmt_name(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  std::string_view t = in.text_of(s.keyword);
  if (t.empty()) t = in.text_of(s.range).substr(0, 20);
  std::string out;
  bool space = false;
  for (char c : t) {   // collapse "Line   Loop" to "Line Loop"
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

}  // namespace

void check_stmt_exprs(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  auto check = [&](ExprId e) {
    if (!e.valid()) return;
    try {
      in.eval(e);
    } catch (const RuntimeError& err) {
      if (err.kind != Diag::NotSupportedYet) throw;   // e.g. Coastline{} inside: its value must wait
    }
  };
  std::visit(
      [&](const auto& n) {
        using T = std::decay_t<decltype(n)>;
        if constexpr (std::is_same_v<T, PointStmt>) {
          check(n.tag), check(n.coords);
        } else if constexpr (std::is_same_v<T, CurveStmt>) {
          check(n.tag), check(n.points), check(n.plane), check(n.knots), check(n.order), check(n.using_n);
        } else if constexpr (std::is_same_v<T, CurveLoopStmt>) {
          check(n.tag), check(n.curves);
        } else if constexpr (std::is_same_v<T, SurfaceStmt>) {
          check(n.tag), check(n.loops), check(n.in_sphere);
        } else if constexpr (std::is_same_v<T, SurfaceLoopStmt>) {
          check(n.tag), check(n.surfaces);
        } else if constexpr (std::is_same_v<T, VolumeStmt>) {
          check(n.tag), check(n.loops);
        } else if constexpr (std::is_same_v<T, SphereStmt>) {
          check(n.tag), check(n.points);
        } else if constexpr (std::is_same_v<T, ParametricSurfaceStmt>) {
          check(n.tag), check(n.fx), check(n.fy), check(n.fz);
        } else if constexpr (std::is_same_v<T, CoordinatesSurfaceStmt>) {
          check(n.geometry);
        } else if constexpr (std::is_same_v<T, PhysicalStmt>) {
          check(n.tag), check(n.name), check(n.entities);
        } else if constexpr (std::is_same_v<T, CoherenceStmt>) {
          check(n.points);
        } else if constexpr (std::is_same_v<T, SplitCurveStmt>) {
          check(n.curve), check(n.points);
        } else if constexpr (std::is_same_v<T, EmbedStmt>) {
          check(n.tags), check(n.target_tag);
        } else if constexpr (std::is_same_v<T, MeshSizeStmt>) {
          check(n.points), check(n.size);
        } else if constexpr (std::is_same_v<T, TransfiniteCurveStmt>) {
          check(n.curves), check(n.nodes), check(n.coef);
        } else if constexpr (std::is_same_v<T, TransfiniteSurfaceStmt>) {
          check(n.surfaces), check(n.corners);
        } else if constexpr (std::is_same_v<T, RecombineStmt>) {
          check(n.tags), check(n.angle);
        } else if constexpr (std::is_same_v<T, EntitySettingStmt>) {
          check(n.tags), check(n.value);
        } else if constexpr (std::is_same_v<T, PeriodicStmt>) {
          check(n.slaves), check(n.masters), check(n.slave_surface), check(n.master_surface);
          for (ExprId e : n.transform_args) check(e);
        } else if constexpr (std::is_same_v<T, ReverseMeshStmt> || std::is_same_v<T, CompoundStmt>) {
          check(n.tags);
        } else if constexpr (std::is_same_v<T, FieldNewStmt> || std::is_same_v<T, FieldActionStmt> ||
                             std::is_same_v<T, DeleteFieldStmt> || std::is_same_v<T, CoastlineNewStmt> ||
                             std::is_same_v<T, CoastlineActionStmt> || std::is_same_v<T, DeleteCoastlineStmt>) {
          check(n.id);
        } else if constexpr (std::is_same_v<T, FieldOptionStmt> || std::is_same_v<T, CoastlineOptionStmt>) {
          check(n.id), check(n.value);
        } else if constexpr (std::is_same_v<T, BackgroundFieldStmt>) {
          check(n.value);
        } else if constexpr (std::is_same_v<T, SetMaxTagStmt>) {
          check(n.tag);
        } else if constexpr (std::is_same_v<T, CommandStmt>) {
          check(n.arg);
        } else if constexpr (std::is_same_v<T, PluginStmt>) {
          check(n.value);
        }
      },
      s.node);
}

void sync_geometry_options(Interpreter& in) {
  geo::ModelOptions& o = in.kernel().model.options();
  const Options& opt = in.options();
  o.tolerance = opt.number("Geometry.Tolerance");
  o.old_new_reg = opt.number("Geometry.OldNewReg") != 0;
  o.auto_coherence = opt.number("Geometry.AutoCoherence") != 0;
  o.old_ruled_surface = opt.number("Geometry.OldRuledSurface") != 0;
}

int to_tag(Interpreter& in, double v, SourceRange at) {
  if (!std::isfinite(v) || std::fabs(v) > std::numeric_limits<int>::max())
    in.fail(at, Diag::InvalidEntityTag, v);
  return static_cast<int>(v);
}

int eval_tag(Interpreter& in, ExprId e) { return to_tag(in, in.eval_number(e), in.ast().expr(e).range); }

std::vector<int> eval_tags(Interpreter& in, ExprId e) {
  std::vector<int> out;
  if (!e.valid()) return out;
  const SourceRange at = in.ast().expr(e).range;
  for (double v : in.eval_numbers(e)) out.push_back(to_tag(in, v, at));
  return out;
}

namespace {

int dim_of(EntityKind e) { return static_cast<int>(e); }

geo::CurveKind curve_kind(CurveKind k) {
  switch (k) {
    case CurveKind::Line: return geo::CurveKind::Line;
    case CurveKind::Spline: return geo::CurveKind::Spline;
    case CurveKind::BSpline: return geo::CurveKind::BSpline;
    case CurveKind::Bezier: return geo::CurveKind::Bezier;
    case CurveKind::Circle: return geo::CurveKind::Circle;
    case CurveKind::Ellipse: return geo::CurveKind::Ellipse;
    default: return geo::CurveKind::Line;   // Nurbs and compounds never get here
  }
}

// A kernel status: on failure, the located diagnostic with provenance notes.
void check(Interpreter& in, const geo::GeoStatus& st, SourceRange at) {
  if (!st) fail_geo(in, at, st.error());
}

Vec3 eval_vec3(Interpreter& in, ExprId e, const char* what) {
  const std::vector<double> v = in.eval_numbers(e);
  if (v.size() != 3)
    in.fail(in.ast().expr(e).range, Diag::ListNeedsNumbers, what, std::size_t{3}, v.size());
  return {v[0], v[1], v[2]};
}

// Kernel errors point at the whole statement (the caret underlines it, from its first word).
SourceRange where(const Stmt& s) { return s.range; }

std::optional<geo::DimTag> exec_point(Interpreter& in, const Stmt& s, const PointStmt& n) {
  const int tag = eval_tag(in, n.tag);
  const std::vector<double> c = in.eval_numbers(n.coords);
  if (c.size() != 3 && c.size() != 4)
    in.fail(in.ast().expr(n.coords).range, Diag::ListPointCoordinates, c.size());
  // Gmsh scales coordinates and the size (and, on a sphere, (u, v)) by Geometry.ScalingFactor.
  const double f = in.options().number("Geometry.ScalingFactor");
  const double lc = c.size() == 4 ? f * c[3] : 0.0;
  check(in, in.kernel().model.add_point(tag, {f * c[0], f * c[1], f * c[2]}, lc), where(s));
  return geo::DimTag{0, tag};
}

std::optional<geo::DimTag> exec_curve(Interpreter& in, StmtId id, const Stmt& s, const CurveStmt& n) {
  if (n.kind == CurveKind::CompoundSpline || n.kind == CurveKind::CompoundBSpline)
    return exec_compound_spline(in, s, n);
  if (n.kind == CurveKind::Nurbs) {
    check_stmt_exprs(in, id);
    in.not_supported_stmt(id, stmt_name(in, id));
    return std::nullopt;
  }
  const int tag = eval_tag(in, n.tag);
  const std::vector<int> points = eval_tags(in, n.points);
  std::optional<Vec3> normal;
  if (n.plane.valid()) normal = eval_vec3(in, n.plane, "Plane{}");
  check(in, in.kernel().model.add_curve(tag, curve_kind(n.kind), points, normal), where(s));
  return geo::DimTag{1, tag};
}

std::optional<geo::DimTag> exec_surface(Interpreter& in, const Stmt& s, const SurfaceStmt& n) {
  const int tag = eval_tag(in, n.tag);
  const std::vector<int> loops = eval_tags(in, n.loops);
  geo::Model& m = in.kernel().model;
  if (n.kind == SurfaceKind::Plane) {
    check(in, m.add_plane_surface(tag, loops), where(s));
  } else {
    std::optional<int> centre;
    if (n.in_sphere.valid()) centre = eval_tag(in, n.in_sphere);
    check(in, m.add_surface_filling(tag, loops, centre), where(s));
  }
  return geo::DimTag{2, tag};
}

void exec_physical(Interpreter& in, const Stmt& s, const PhysicalStmt& n) {
  std::optional<int> tag;
  std::string name;
  if (n.name.valid()) name = in.eval_string(n.name);
  if (n.tag.valid()) {
    // `Physical Curve(s)` with a string variable s is the name form.
    const Value v = in.eval(n.tag);
    if (v.is_string())
      name = v.strs().empty() ? "" : v.strs()[0];
    else
      tag = to_tag(in, v.nums().empty() ? 0.0 : v.nums()[0], in.ast().expr(n.tag).range);
  }
  const std::vector<int> entities = eval_tags(in, n.entities);
  geo::PhysicalOp op = geo::PhysicalOp::Assign;
  if (n.op == AffOp::Add) op = geo::PhysicalOp::Add;
  else if (n.op == AffOp::Sub) op = geo::PhysicalOp::Remove;
  else if (n.op != AffOp::Assign)
    in.fail(where(s), Diag::PhysicalGroupOperator, affop_text(n.op));
  const int dim = dim_of(n.ent);
  auto r = in.kernel().model.add_physical(dim, tag, name, entities, op);
  if (!r) fail_geo(in, where(s), r.error());
  if (in.kernel().created_at.count({kPhysicalKeyBase + dim, *r}) == 0)
    record_created(in.kernel(), kPhysicalKeyBase + dim, *r, where(s));
}

void exec_delete_shapes(Interpreter& in, const Stmt& s, const DeleteShapesStmt& n) {
  const std::vector<geo::DimTag> ents = eval_shape_block(in, n.shapes, false);
  std::vector<geo::DimTag> skipped;
  check(in, in.kernel().model.remove(ents, n.recursive, &skipped), where(s));
  if (skipped.empty()) return;
  // Gmsh skips these silently; a warning says why they are still there.
  std::string list;
  for (const geo::DimTag& d : skipped)
    list += fmt::format("{}{} {}", list.empty() ? "" : ", ", d.dim == 0 ? "point" : d.dim == 1 ? "curve" : "surface",
                        std::abs(d.tag));
  in.diags().report(s.keyword.valid() ? s.keyword : s.range, Diag::GeoDeleteSkipped, list);
}

void exec_split_curve(Interpreter& in, const Stmt& s, const SplitCurveStmt& n) {
  const int curve = eval_tag(in, n.curve);
  const std::vector<int> points = eval_tags(in, n.points);
  auto r = in.kernel().model.split_curve(curve, points);
  if (!r) fail_geo(in, where(s), r.error());
  for (int c : *r) record_created(in.kernel(), 1, c, where(s));
}

}  // namespace

void report_compat_notes(Interpreter& in, SourceRange at) {
  for (const geo::Model::CompatNote& note : in.kernel().model.take_compat_notes()) {
    const GeoDiagnostic d = geo_compat_diagnostic(note);
    in.diags().report_message(at, d.kind, d.message);
  }
}

namespace {

// Reports the notes of a statement when it ends, also when it fails after leaving some.
class CompatNotesAtEnd {
 public:
  CompatNotesAtEnd(Interpreter& in, SourceRange at) : in_(in), at_(at) {}
  CompatNotesAtEnd(const CompatNotesAtEnd&) = delete;
  CompatNotesAtEnd& operator=(const CompatNotesAtEnd&) = delete;
  ~CompatNotesAtEnd() { report_compat_notes(in_, at_); }

 private:
  Interpreter& in_;
  SourceRange at_;
};

}  // namespace

std::optional<geo::DimTag> create_geometry(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  const CompatNotesAtEnd notes{in, where(s)};
  sync_geometry_options(in);
  KernelState& k = in.kernel();
  geo::Model& m = k.model;
  std::optional<geo::DimTag> made;
  switch (s.kind()) {
    case StmtKind::Point: made = exec_point(in, s, std::get<PointStmt>(s.node)); break;
    case StmtKind::Curve: made = exec_curve(in, id, s, std::get<CurveStmt>(s.node)); break;
    case StmtKind::CurveLoop: {
      const auto& n = std::get<CurveLoopStmt>(s.node);
      const int tag = eval_tag(in, n.tag);
      check(in, m.add_curve_loop(tag, eval_tags(in, n.curves)), where(s));
      record_created(k, kCurveLoopKey, tag, where(s));
      return std::nullopt;
    }
    case StmtKind::Surface: made = exec_surface(in, s, std::get<SurfaceStmt>(s.node)); break;
    case StmtKind::SurfaceLoop: {
      const auto& n = std::get<SurfaceLoopStmt>(s.node);
      const int tag = eval_tag(in, n.tag);
      check(in, m.add_surface_loop(tag, eval_tags(in, n.surfaces)), where(s));
      return std::nullopt;
    }
    case StmtKind::Volume: {
      const auto& n = std::get<VolumeStmt>(s.node);
      const int tag = eval_tag(in, n.tag);
      check(in, m.add_volume(tag, eval_tags(in, n.loops)), where(s));
      made = geo::DimTag{3, tag};
      break;
    }
    case StmtKind::Sphere: {
      const auto& n = std::get<SphereStmt>(s.node);
      const int tag = eval_tag(in, n.tag);
      const std::vector<int> pts = eval_tags(in, n.points);
      if (pts.size() != 2)
        in.fail(in.ast().expr(n.points).range, Diag::ListSpherePoints, stmt_name(in, id), pts.size());
      check(in, n.polar ? m.add_polar_sphere(tag, pts[0], pts[1]) : m.add_lonlat_sphere(tag, pts[0], pts[1]), where(s));
      record_created(k, kGeometryKey, tag, where(s));
      return std::nullopt;
    }
    case StmtKind::CoordinatesSurface:
      check(in, m.set_current_geometry(eval_tag(in, std::get<CoordinatesSurfaceStmt>(s.node).geometry)), where(s));
      return std::nullopt;
    case StmtKind::EuclideanCoordinates: m.set_euclidean(); return std::nullopt;
    case StmtKind::Physical: exec_physical(in, s, std::get<PhysicalStmt>(s.node)); return std::nullopt;
    case StmtKind::Coherence:
      if (std::get<CoherenceStmt>(s.node).what == CoherenceKind::Geometry) {
        m.coherence();
        return std::nullopt;
      }
      break;   // `Coherence Point{...}`: below
    case StmtKind::SplitCurve: exec_split_curve(in, s, std::get<SplitCurveStmt>(s.node)); return std::nullopt;
    case StmtKind::ShapeExpr: eval_shape_expr(in, std::get<ShapeExprStmt>(s.node).expr); return std::nullopt;
    case StmtKind::DeleteShapes: exec_delete_shapes(in, s, std::get<DeleteShapesStmt>(s.node)); return std::nullopt;
    case StmtKind::Embed: {
      const auto& n = std::get<EmbedStmt>(s.node);
      if (n.target == EntityKind::Volume) {
        embed_in_volume(in, s, n);
        return std::nullopt;
      }
      if (n.target != EntityKind::Surface || n.ent == EntityKind::Surface || n.ent == EntityKind::Volume) break;
      const std::vector<int> tags = eval_tags(in, n.tags);
      check(in, m.embed(dim_of(n.ent), tags, eval_tag(in, n.target_tag)), where(s));
      return std::nullopt;
    }
    case StmtKind::MeshSize: {
      const auto& n = std::get<MeshSizeStmt>(s.node);
      const std::vector<int> points = n.all ? m.tags(0) : eval_tags(in, n.points);
      check(in, m.set_mesh_size(points, in.eval_number(n.size)), where(s));
      return std::nullopt;
    }
    case StmtKind::SetMaxTag: {
      const auto& n = std::get<SetMaxTagStmt>(s.node);
      m.set_max_tag(dim_of(n.ent), eval_tag(in, n.tag));
      return std::nullopt;
    }
    default: break;
  }
  if (made) {
    record_created(k, made->dim, made->tag, where(s));
    return made;
  }
  if (s.kind() == StmtKind::Curve) return std::nullopt;   // a kind reported as not supported
  // Parametric Surface, Coherence Point{}, embedding in a volume and
  // the mesh constraints other than Transfinite and Recombine (MeshAlgorithm, Smoother,
  // Periodic, ReverseMesh; mesh_constraints.cpp has those two, compound.cpp the compounds): the model has
  // no place for them yet.
  check_stmt_exprs(in, id);
  in.not_supported_stmt(id, stmt_name(in, id));
  return std::nullopt;
}

void exec_geometry_stmt(Interpreter& in, StmtId id) { create_geometry(in, id); }

void exec_set_factory_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  const std::string name = in.eval_string(std::get<SetFactoryStmt>(s.node).name);
  if (name == "Built-in" || name == "Gmsh") return;   // the default kernel: nothing to do
  in.fail_fmt(s.range, Diag::NotSupportedYet, fmt::format("SetFactory(\"{}\")", name),
              ": only the built-in kernel exists");
}

void exec_coherence_stmt(Interpreter& in, StmtId id) {
  if (std::get<CoherenceStmt>(in.ast().stmt(id).node).what == CoherenceKind::Mesh)
    exec_mesh_stmt(in, id);
  else
    create_geometry(in, id);
}

double new_tag_constant(Interpreter& in, Constant c) {
  sync_geometry_options(in);
  const geo::Model& m = in.kernel().model;
  switch (c) {
    case Constant::NewP: return m.new_point_tag();
    case Constant::NewL:
    case Constant::NewC: return m.new_curve_tag();
    case Constant::NewLL:
    case Constant::NewCL: return m.new_loop_tag();
    case Constant::NewS: return m.new_surface_tag();
    case Constant::NewSL: return m.options().old_new_reg ? m.new_reg() : m.new_surface_loop_tag();
    case Constant::NewV: return m.options().old_new_reg ? m.new_reg() : m.new_volume_tag();
    case Constant::NewF: return in.kernel().fields.next_id();
    default: return m.new_reg();
  }
}

}  // namespace sm::interp
