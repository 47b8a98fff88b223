// Geometry statements and model queries. The geometry kernel arrives with a
// later issue; until then each statement reports 'not supported yet' (once per
// kind) and queries that need the model are errors. new* tags answer for the
// empty model, which is exact while no entity can be created.
#include <fmt/format.h>

#include "interp/builtins/dispatch.h"
#include "interp/interpreter.h"

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
      if (err.kind != Diag::NotSupportedYet) throw;   // a model query: its value must wait
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
          check(n.slaves), check(n.masters);
          for (ExprId e : n.translate) check(e);
        } else if constexpr (std::is_same_v<T, ReverseMeshStmt> || std::is_same_v<T, CompoundStmt>) {
          check(n.tags);
        } else if constexpr (std::is_same_v<T, FieldNewStmt> || std::is_same_v<T, FieldActionStmt> ||
                             std::is_same_v<T, DeleteFieldStmt>) {
          check(n.id);
        } else if constexpr (std::is_same_v<T, FieldOptionStmt>) {
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

void dispatch_model_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  switch (s.kind()) {
    case StmtKind::FieldNew:
    case StmtKind::FieldOption:
    case StmtKind::FieldAction:
    case StmtKind::BackgroundField:
    case StmtKind::DeleteField:
      exec_field_stmt(in, id);
      return;
    case StmtKind::Plugin:
    case StmtKind::View:
    case StmtKind::Color:
      exec_mesh_stmt(in, id);
      return;
    case StmtKind::Coherence:
      if (std::get<CoherenceStmt>(s.node).what == CoherenceKind::Mesh) {
        exec_mesh_stmt(in, id);
        return;
      }
      break;
    case StmtKind::SetFactory: {
      const std::string name = in.eval_string(std::get<SetFactoryStmt>(s.node).name);
      if (name == "Built-in" || name == "Gmsh") return;   // the default kernel: nothing to do
      in.fail_fmt(s.range, Diag::NotSupportedYet, fmt::format("SetFactory(\"{}\")", name),
                  ": only the built-in kernel exists");
    }
    default:
      break;
  }
  check_stmt_exprs(in, id);
  in.not_supported_stmt(id, stmt_name(in, id));
}

double new_tag_constant(Interpreter&, Constant) { return 1; }

void eval_model_expr(Interpreter& in, ExprId e) {
  const Expr& x = in.ast().expr(e);
  std::string what;
  switch (x.kind()) {
    case ExprKind::EntityQuery: {
      const auto& q = std::get<EntityQueryExpr>(x.node);
      what = fmt::format("{}{}{{}}", q.physical ? "Physical " : "", entity_name(q.ent));
      break;
    }
    case ExprKind::EntityInBox: what = "In BoundingBox"; break;
    case ExprKind::Boundary: what = "Boundary{}"; break;
    case ExprKind::Transform: {
      static const char* kNames[] = {"Translate", "Rotate", "Symmetry", "Dilate", "Duplicata"};
      what = kNames[static_cast<int>(std::get<TransformExpr>(x.node).kind)];
      break;
    }
    case ExprKind::CoastlineQuery: what = "Coastline{}"; break;
    default: what = std::string(in.text_of(x.range).substr(0, 30)); break;
  }
  in.not_supported_expr(e, what);
}

}  // namespace sm::interp
