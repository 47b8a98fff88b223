// Entry points of the statements and expressions that need the geometry model,
// fields or the mesher. Each family file (geometry.cpp, fields.cpp,
// mesh_commands.cpp) owns its part, so later issues replace them file by file.
#pragma once

#include <string>
#include <string_view>

#include "interp/value.h"
#include "lang/ast.h"

namespace sm::interp {

class Interpreter;

/// Any statement the core evaluator does not run itself (geometry, physical
/// groups, mesh constraints, fields, plugins, views).
void dispatch_model_stmt(Interpreter& in, lang::StmtId s);
/// Field statements (`Field[1] = Distance;`, options, actions, Background Field).
void exec_field_stmt(Interpreter& in, lang::StmtId s);
/// `FieldValue(n, x, y, z)` / `FieldArgmin(...)` (native, field_eval.cpp): the
/// MODEL_BUILTIN rows of lang/builtin_functions.def. Checks its own arguments.
Value eval_field_call(Interpreter& in, const lang::Expr& e, const lang::CallExpr& c);
/// `Mesh 2;`, `Save "f";`, `Merge`, ... (`CommandStmt`s other than Include).
/// Returns false for an unknown command name.
bool exec_mesh_command(Interpreter& in, lang::StmtId s, std::string_view command);
/// Mesh-side statements without a command word: Plugin, View, Color, Coherence Mesh.
void exec_mesh_stmt(Interpreter& in, lang::StmtId s);

/// `Coastline[n] = Format;`, `Coastline[n].Option = v;`, `Delete Coastline[n];` and
/// `Plugin(GSHHS)...;` (coastline.cpp, plugin_gshhs.cpp): runs them and returns true, or
/// returns false for any other statement.
bool exec_native_coast_stmt(Interpreter& in, lang::StmtId s);
void exec_coastline_stmt(Interpreter& in, lang::StmtId s);
void exec_gshhs_plugin_stmt(Interpreter& in, lang::StmtId s);
/// `Coastline{n, ...}` (coastline.cpp): imports coastline n on first use and returns its
/// curve-loop tags (or, with a string item, its "Curves", "OpenCurves", "Points"...).
Value eval_coastline_query(Interpreter& in, lang::ExprId e);

/// Evaluates the expressions of a statement the kernel cannot run yet, so
/// that mistakes in them (unknown variables, division by zero...) are
/// reported now; parts that need the model themselves are skipped.
void check_stmt_exprs(Interpreter& in, lang::StmtId s);

/// newp, newl, newc, newll, news, newsl, newv, newreg, newf.
double new_tag_constant(Interpreter& in, lang::Constant c);
/// Entity queries, transforms, Boundary{}, Coastline{}: expressions needing the model.
Value eval_model_expr(Interpreter& in, lang::ExprId e);
/// Where a string is expected, Gmsh reads `Physical Curve{t}` as the group's name: true
/// (and the name in `out`, "" for an unnamed or unknown group) when `e` is such a query.
bool physical_group_name(Interpreter& in, lang::ExprId e, std::string& out);

}  // namespace sm::interp
