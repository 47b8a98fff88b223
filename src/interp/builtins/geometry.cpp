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
