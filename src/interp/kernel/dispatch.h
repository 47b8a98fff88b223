// Entry points of the statements and expressions that need the geometry model,
// fields, coastlines or the mesher: the handlers kernel/statements.def names, and the
// expressions the evaluator hands over. Each family file owns its part.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/value.h"
#include "lang/ast.h"

namespace sm::interp {

class Interpreter;
struct KernelState;

// The handlers of kernel/statements.def's rows, each with the rows it serves.

/// Geometry (geometry.cpp): Point ... Physical, transforms as statements, Delete{},
/// MeshSize, embedding; Surface Loop, Volume and the mesh constraints other than
/// Transfinite and Recombine are reported as not supported.
void exec_geometry_stmt(Interpreter& in, lang::StmtId s);
/// `Transfinite Curve|Surface ...;`, `Recombine Surface{...};` (mesh_constraints.cpp): the
/// kernel state's mesh constraints.
void exec_mesh_constraint_stmt(Interpreter& in, lang::StmtId s);
/// `Compound Curve|Surface{...};` (compound.cpp): a group meshed as one.
void exec_compound_stmt(Interpreter& in, lang::StmtId s);
/// `SetFactory("Built-in");` (geometry.cpp): the only kernel there is.
void exec_set_factory_stmt(Interpreter& in, lang::StmtId s);
/// `Coherence;` / `Coherence Point{...}` (geometry.cpp); `Coherence Mesh;` goes to exec_mesh_stmt.
void exec_coherence_stmt(Interpreter& in, lang::StmtId s);
/// Field statements (fields.cpp): `Field[1] = Distance;`, options, actions, `Delete
/// Field[n];`, Background Field.
void exec_field_stmt(Interpreter& in, lang::StmtId s);
/// `Coastline[n] = Format;`, `Coastline[n].Option = v;`, `Delete Coastline[n];` (coastline.cpp).
void exec_coastline_stmt(Interpreter& in, lang::StmtId s);
/// `Plugin(Name)...;` (plugin_gshhs.cpp): Plugin(GSHHS) runs, other plugins go to exec_mesh_stmt.
void exec_plugin_stmt(Interpreter& in, lang::StmtId s);
/// Mesh-side statements without a command word (mesh_commands.cpp): Plugin, View, Color,
/// Coherence Mesh, all reported as not supported.
void exec_mesh_stmt(Interpreter& in, lang::StmtId s);

/// `FieldValue(n, x, y, z)` / `FieldArgmin(...)` (native, field_eval.cpp): the
/// MODEL_BUILTIN rows of lang/builtin_functions.def. Checks its own arguments.
Value eval_field_call(Interpreter& in, const lang::Expr& e, const lang::CallExpr& c);
/// `Merge "file";` (merge.cpp): a missing file is an error at its name; a mesh file
/// (.msh) becomes discrete entities (merge_mesh_file), views are display only, the other
/// kinds Gmsh reads are reported as not supported.
void exec_merge(Interpreter& in, lang::StmtId s, const lang::CommandStmt& c);
/// `CreateGeometry;` (create_geometry.cpp): the discrete curves and flat discrete surfaces
/// of merged meshes get a geometry from their mesh and are remeshed; a located warning when
/// there is none left to do.
void exec_create_geometry(Interpreter& in, lang::StmtId s);
/// The mesh file at `path` (`name` as the script wrote it) into discrete entities of the
/// model (merge_mesh.cpp); errors are at `at`.
void merge_mesh_file(Interpreter& in, const std::filesystem::path& path, const std::string& name,
                     lang::SourceRange at);
/// `Mesh 2;`, `Save "f";`, `Merge`, ... (`CommandStmt`s other than Include).
/// Returns false for an unknown command name.
bool exec_mesh_command(Interpreter& in, lang::StmtId s, std::string_view command);

/// `Coastline{n, ...}` (coastline.cpp): imports coastline n on first use and returns its
/// curve-loop tags (or, with a string item, its "Curves", "OpenCurves", "Points"...).
Value eval_coastline_query(Interpreter& in, lang::ExprId e);

/// The coast curves Coastline[id]'s import created, its open boundaries (region cuts)
/// left out (coastline.cpp); nullopt if it is not defined or not imported yet (ChannelWidth's CoastlineId,
/// Mesh.ElementsAcrossChannels).
std::optional<std::vector<int>> coastline_curves(const KernelState& k, int id);

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
