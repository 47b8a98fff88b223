// Shared by the geometry statement and query files: tags from expressions, entity lists
// from shape blocks (`{ Point{1}; Curve{2:4}; }`), and running a creation statement that
// appears inside such a block.
#pragma once

#include <optional>
#include <vector>

#include "geo/model.h"
#include "lang/ast.h"

namespace sm::interp {

class Interpreter;

/// Copies the Geometry.* options the kernel reads (Tolerance, OldNewReg, AutoCoherence).
void sync_geometry_options(Interpreter& in);

/// An entity tag: the number truncated toward zero as Gmsh does; an error when it is
/// not finite or out of the int range.
int to_tag(Interpreter& in, double v, lang::SourceRange at);
int eval_tag(Interpreter& in, lang::ExprId e);
/// Every number of a (list) expression as tags.
std::vector<int> eval_tags(Interpreter& in, lang::ExprId e);

/// The entities of a shape block, in order. `keep_sign` keeps `-c` (Boundary); else tags
/// are made positive. Creation items run their statement; nested transforms run.
std::vector<geo::DimTag> eval_shape_block(Interpreter& in, const lang::ShapeBlock& block, bool keep_sign);

/// A Translate/Rotate/Symmetry/Dilate/Duplicata/Boundary expression as entities.
std::vector<geo::DimTag> eval_shape_expr(Interpreter& in, lang::ExprId e);

/// `Extrude {...} {...}` (kernel/extrude.cpp): the new entities in Gmsh's order.
std::vector<geo::DimTag> apply_extrude(Interpreter& in, const lang::Expr& x, const lang::TransformExpr& t);

/// `Point|Curve|Surface{...} In Volume{v};` (kernel/extrude.cpp): checked, then kept by no
/// one, since only 3D meshing would use it.
void embed_in_volume(Interpreter& in, const lang::Stmt& s, const lang::EmbedStmt& n);

/// Reports the kernel's compat notes (geo::Model::take_compat_notes) as gmsh-compat
/// warnings at `at`.
void report_compat_notes(Interpreter& in, lang::SourceRange at);

/// Runs a geometry statement (exec_geometry_stmt, kernel/dispatch.h); returns the
/// elementary entity it created, if any, for a creation inside a shape block.
std::optional<geo::DimTag> create_geometry(Interpreter& in, lang::StmtId s);

}  // namespace sm::interp
