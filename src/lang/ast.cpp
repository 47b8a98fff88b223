// Ast storage (node arrays, string interning), the built-in constant table,
// and the S-expression dump used by tests.
#include "lang/ast.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace sm::lang {

namespace {

struct ConstantEntry {
  std::string_view text;
  Constant which;
};
constexpr ConstantEntry kConstants[] = {
    {"Pi", Constant::Pi},
    {"newp", Constant::NewP},
    {"newl", Constant::NewL},
    {"newc", Constant::NewC},
    {"newll", Constant::NewLL},
    {"newcl", Constant::NewCL},
    {"news", Constant::NewS},
    {"newsl", Constant::NewSL},
    {"newv", Constant::NewV},
    {"newreg", Constant::NewReg},
    {"newf", Constant::NewF},
    {"GMSH_MAJOR_VERSION", Constant::GmshMajorVersion},
    {"GMSH_MINOR_VERSION", Constant::GmshMinorVersion},
    {"GMSH_PATCH_VERSION", Constant::GmshPatchVersion},
    {"MPI_Size", Constant::MpiSize},
    {"MPI_Rank", Constant::MpiRank},
    {"Cpu", Constant::Cpu},
    {"Memory", Constant::Memory},
    {"TotalMemory", Constant::TotalMemory},
    {"Today", Constant::Today},
    {"CurrentDirectory", Constant::CurrentDirectory},
    {"CurrentDir", Constant::CurrentDirectory},
    {"CurrentFileName", Constant::CurrentFileName},
    {"GmshExecutableName", Constant::GmshExecutableName},
    {"OnelabAction", Constant::OnelabAction},
};

#define SM_CHECK_KIND(Enum, Variant, kind, Type) \
  static_assert(std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(Enum::kind), Variant>, Type>);
SM_CHECK_KIND(ExprKind, ExprNode, Error, ErrorExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Number, NumberExpr)
SM_CHECK_KIND(ExprKind, ExprNode, String, StringExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Var, VarExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Constant, ConstantExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Unary, UnaryExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Binary, BinaryExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Ternary, TernaryExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Postfix, PostfixExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Index, IndexExpr)
SM_CHECK_KIND(ExprKind, ExprNode, WholeList, WholeListExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Slice, SliceExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Length, LengthExpr)
SM_CHECK_KIND(ExprKind, ExprNode, List, ListExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Range, RangeExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Call, CallExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Option, OptionExpr)
SM_CHECK_KIND(ExprKind, ExprNode, EntityQuery, EntityQueryExpr)
SM_CHECK_KIND(ExprKind, ExprNode, EntityInBox, EntityInBoxExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Boundary, BoundaryExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Transform, TransformExpr)
SM_CHECK_KIND(ExprKind, ExprNode, CoastlineQuery, CoastlineQueryExpr)
SM_CHECK_KIND(ExprKind, ExprNode, Intersect, IntersectExpr)
SM_CHECK_KIND(StmtKind, StmtNode, Assign, AssignStmt)
SM_CHECK_KIND(StmtKind, StmtNode, IncDec, IncDecStmt)
SM_CHECK_KIND(StmtKind, StmtNode, DefineConstant, DefineConstantStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Delete, DeleteStmt)
SM_CHECK_KIND(StmtKind, StmtNode, DeleteField, DeleteFieldStmt)
SM_CHECK_KIND(StmtKind, StmtNode, DeleteCoastline, DeleteCoastlineStmt)
SM_CHECK_KIND(StmtKind, StmtNode, DeleteShapes, DeleteShapesStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Print, PrintStmt)
SM_CHECK_KIND(StmtKind, StmtNode, If, IfStmt)
SM_CHECK_KIND(StmtKind, StmtNode, For, ForStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Macro, MacroStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Call, CallStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Return, ReturnStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Exit, ExitStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Abort, AbortStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Assert, AssertStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Include, IncludeStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Command, CommandStmt)
SM_CHECK_KIND(StmtKind, StmtNode, SetFactory, SetFactoryStmt)
SM_CHECK_KIND(StmtKind, StmtNode, SetMaxTag, SetMaxTagStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Point, PointStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Curve, CurveStmt)
SM_CHECK_KIND(StmtKind, StmtNode, CurveLoop, CurveLoopStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Surface, SurfaceStmt)
SM_CHECK_KIND(StmtKind, StmtNode, SurfaceLoop, SurfaceLoopStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Volume, VolumeStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Sphere, SphereStmt)
SM_CHECK_KIND(StmtKind, StmtNode, ParametricSurface, ParametricSurfaceStmt)
SM_CHECK_KIND(StmtKind, StmtNode, CoordinatesSurface, CoordinatesSurfaceStmt)
SM_CHECK_KIND(StmtKind, StmtNode, EuclideanCoordinates, EuclideanCoordinatesStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Physical, PhysicalStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Coherence, CoherenceStmt)
SM_CHECK_KIND(StmtKind, StmtNode, SplitCurve, SplitCurveStmt)
SM_CHECK_KIND(StmtKind, StmtNode, ShapeExpr, ShapeExprStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Embed, EmbedStmt)
SM_CHECK_KIND(StmtKind, StmtNode, MeshSize, MeshSizeStmt)
SM_CHECK_KIND(StmtKind, StmtNode, TransfiniteCurve, TransfiniteCurveStmt)
SM_CHECK_KIND(StmtKind, StmtNode, TransfiniteSurface, TransfiniteSurfaceStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Recombine, RecombineStmt)
SM_CHECK_KIND(StmtKind, StmtNode, EntitySetting, EntitySettingStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Periodic, PeriodicStmt)
SM_CHECK_KIND(StmtKind, StmtNode, ReverseMesh, ReverseMeshStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Compound, CompoundStmt)
SM_CHECK_KIND(StmtKind, StmtNode, FieldNew, FieldNewStmt)
SM_CHECK_KIND(StmtKind, StmtNode, FieldOption, FieldOptionStmt)
SM_CHECK_KIND(StmtKind, StmtNode, FieldAction, FieldActionStmt)
SM_CHECK_KIND(StmtKind, StmtNode, CoastlineNew, CoastlineNewStmt)
SM_CHECK_KIND(StmtKind, StmtNode, CoastlineOption, CoastlineOptionStmt)
SM_CHECK_KIND(StmtKind, StmtNode, CoastlineAction, CoastlineActionStmt)
SM_CHECK_KIND(StmtKind, StmtNode, BackgroundField, BackgroundFieldStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Plugin, PluginStmt)
SM_CHECK_KIND(StmtKind, StmtNode, View, ViewStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Color, ColorStmt)
SM_CHECK_KIND(StmtKind, StmtNode, Visibility, VisibilityStmt)
#undef SM_CHECK_KIND
static_assert(std::variant_size_v<ExprNode> == static_cast<std::size_t>(ExprKind::Intersect) + 1);
static_assert(std::variant_size_v<StmtNode> == static_cast<std::size_t>(StmtKind::Visibility) + 1);

}  // namespace

std::string_view entity_name(EntityKind e) {
  switch (e) {
    case EntityKind::Point: return "Point";
    case EntityKind::Curve: return "Curve";
    case EntityKind::Surface: return "Surface";
    case EntityKind::Volume: return "Volume";
  }
  return "?";
}

std::string_view affop_text(AffOp op) {
  switch (op) {
    case AffOp::Assign: return "=";
    case AffOp::Add: return "+=";
    case AffOp::Sub: return "-=";
    case AffOp::Mul: return "*=";
    case AffOp::Div: return "/=";
  }
  return "?";
}

Constant constant_from_text(std::string_view text) {
  if (text.empty()) return Constant::kCount;
  for (const auto& e : kConstants)
    if (e.text == text) return e.which;
  return Constant::kCount;
}

std::string_view constant_text(Constant c) {
  for (const auto& e : kConstants)
    if (e.which == c) return e.text;
  return "?";
}

bool constant_is_string(Constant c) { return c >= Constant::Today && c < Constant::kCount; }

ExprId Ast::add_expr(SourceRange range, ExprNode node) {
  exprs_.push_back({range, std::move(node)});
  return ExprId{static_cast<std::uint32_t>(exprs_.size() - 1)};
}

StmtId Ast::add_stmt(SourceRange range, SourceRange keyword, StmtNode node) {
  stmts_.push_back({range, keyword, std::move(node)});
  return StmtId{static_cast<std::uint32_t>(stmts_.size() - 1)};
}

StrId Ast::intern(std::string_view text) {
  if (auto it = string_ids_.find(text); it != string_ids_.end()) return it->second;
  strings_.emplace_back(text);
  const StrId id{static_cast<std::uint32_t>(strings_.size() - 1)};
  string_ids_.emplace(strings_.back(), id);
  return id;
}

StrId Ast::find(std::string_view text) const {
  auto it = string_ids_.find(text);
  return it == string_ids_.end() ? StrId{} : it->second;
}

// ---------------------------------------------------------------- dump

namespace {

class Dumper {
 public:
  explicit Dumper(const Ast& ast) : ast_(ast) {}

  std::string expr(ExprId id) {
    if (!id.valid()) return "_";
    return std::visit([&](const auto& n) { return node(n); }, ast_.expr(id).node);
  }
  std::string stmt(StmtId id) {
    if (!id.valid()) return "_";
    return std::visit([&](const auto& n) { return node(n); }, ast_.stmt(id).node);
  }

 private:
  std::string s(StrId id) { return id.valid() ? std::string(ast_.str(id)) : "_"; }
  std::string list(const ExprList& l) {
    std::string out;
    // Appended piece by piece: GCC 12 reports a false -Wrestrict overlap in `" " + expr(e)`
    // once enough callers inline it.
    for (ExprId e : l) out.append(" ").append(expr(e));
    return out;
  }
  std::string body(const StmtList& l) {
    std::string out = "(";
    for (std::size_t i = 0; i < l.size(); ++i) out += (i ? " " : "") + stmt(l[i]);
    return out + ")";
  }
  std::string name(const Name& n) {
    if (n.from_string.valid()) return "(s2n " + expr(n.from_string) + ")";
    if (n.suffixes.empty()) return s(n.ident);
    std::string out = "(name " + s(n.ident);
    for (ExprId e : n.suffixes) out += " ~" + expr(e);
    return out + ")";
  }
  std::string option(const OptionRef& o) {
    std::string out = s(o.category);
    if (o.index.valid()) out += "[" + expr(o.index) + "]";
    out += "." + s(o.member);
    if (o.sub_member.valid()) out += "." + s(o.sub_member);
    return out;
  }
  static std::string ent(EntityKind e, bool physical = false) {
    return (physical ? "Physical" : "") + std::string(entity_name(e));
  }
  std::string shapes(const ShapeBlock& b) {
    std::string out = "(shapes";
    for (const ShapeItem& it : b) {
      switch (it.kind) {
        case ShapeItem::Kind::Entities:
          out += " (" + ent(it.ent, it.physical) + (it.all ? " :" : "") + list(it.tags) + ")";
          break;
        case ShapeItem::Kind::Create: out += " " + stmt(it.create); break;
        case ShapeItem::Kind::Nested: out += " " + expr(it.nested); break;
      }
    }
    return out + ")";
  }
  std::string lvalue(const LValue& lv) {
    switch (lv.kind) {
      case LValue::Kind::Var: return name(lv.name);
      case LValue::Kind::WholeList: return "(whole " + name(lv.name) + ")";
      case LValue::Kind::Element: return "(index " + name(lv.name) + " " + expr(lv.index) + ")";
      case LValue::Kind::SubList: return "(slice " + name(lv.name) + list(lv.indices) + ")";
      case LValue::Kind::Option: return "(option " + option(lv.option) + ")";
    }
    return "?";
  }
  static std::string op(Tok t) {
    std::string_view n = tok_name(t);
    if (n.size() >= 2 && n.front() == '\'') n = n.substr(1, n.size() - 2);
    return std::string(n);
  }
  static std::string num(double v) { return fmt::format("{}", v); }
  std::string opt(const char* label, ExprId e) { return e.valid() ? std::string(" :") + label + " " + expr(e) : ""; }

  // expressions
  std::string node(const ErrorExpr&) { return "(error)"; }
  std::string node(const NumberExpr& n) { return num(n.value); }
  std::string node(const StringExpr& n) { return "\"" + s(n.text) + "\""; }
  std::string node(const VarExpr& n) { return "(var " + name(n.name) + ")"; }
  std::string node(const ConstantExpr& n) { return "(const " + std::string(constant_text(n.which)) + ")"; }
  std::string node(const UnaryExpr& n) { return "(" + op(n.op) + " " + expr(n.operand) + ")"; }
  std::string node(const BinaryExpr& n) { return "(" + op(n.op) + " " + expr(n.lhs) + " " + expr(n.rhs) + ")"; }
  std::string node(const TernaryExpr& n) {
    return "(? " + expr(n.cond) + " " + expr(n.then_expr) + " " + expr(n.else_expr) + ")";
  }
  std::string node(const PostfixExpr& n) { return "(post" + op(n.op) + " " + expr(n.target) + ")"; }
  std::string node(const IndexExpr& n) { return "(index " + name(n.name) + " " + expr(n.index) + ")"; }
  std::string node(const WholeListExpr& n) { return "(whole " + name(n.name) + ")"; }
  std::string node(const SliceExpr& n) { return "(slice " + name(n.name) + list(n.indices) + ")"; }
  std::string node(const LengthExpr& n) { return "(# " + expr(n.list) + ")"; }
  std::string node(const ListExpr& n) { return "(list" + list(n.items) + ")"; }
  std::string node(const RangeExpr& n) {
    return "(range " + expr(n.from) + " " + expr(n.to) + (n.step.valid() ? " " + expr(n.step) : "") + ")";
  }
  std::string node(const CallExpr& n) { return "(call " + s(n.func) + list(n.args) + ")"; }
  std::string node(const OptionExpr& n) { return "(option " + option(n.option) + ")"; }
  std::string node(const EntityQueryExpr& n) {
    return "(query " + ent(n.ent, n.physical) + (n.all ? " :" : "") + list(n.tags) + ")";
  }
  std::string node(const EntityInBoxExpr& n) { return "(in-box " + ent(n.ent) + list(n.box) + ")"; }
  std::string node(const BoundaryExpr& n) {
    static constexpr std::string_view kNames[] = {"Boundary", "CombinedBoundary", "PointsOf"};
    return "(" + std::string(kNames[static_cast<int>(n.kind)]) + " " + shapes(n.shapes) + ")";
  }
  std::string node(const TransformExpr& n) {
    static constexpr std::string_view kNames[] = {"Translate", "Rotate", "Symmetry", "Dilate", "Duplicata", "Extrude"};
    std::string out =
        "(" + std::string(kNames[static_cast<int>(n.kind)]) + " (params" + list(n.params) + ") " + shapes(n.shapes);
    // Extrude's mesh parameters by count only: more list() calls here make GCC 12 inline
    // differently and report a false -Wrestrict overlap elsewhere in this file.
    if (!n.extrude.layers.empty()) out.append(fmt::format(" (layers {})", n.extrude.layers.size()));
    if (n.extrude.has_recombine) out.append(" (recombine)");
    out.push_back(')');
    return out;
  }
  std::string node(const CoastlineQueryExpr& n) { return "(coastline" + list(n.ids) + ")"; }
  std::string node(const IntersectExpr& n) { return "(intersect" + list(n.curves) + " " + expr(n.surface) + ")"; }

  // statements
  std::string node(const AssignStmt& n) {
    return "(assign " + std::string(affop_text(n.op)) + " " + lvalue(n.target) + " " + expr(n.value) + ")";
  }
  std::string node(const IncDecStmt& n) { return std::string(n.increment ? "(++ " : "(-- ") + lvalue(n.target) + ")"; }
  std::string node(const DefineConstantStmt& n) {
    std::string out = "(define-constant";
    for (const DefineEntry& e : n.entries) {
      out += " (" + name(e.name) + " " + expr(e.value);
      for (const OnelabAttr& a : e.attrs) {
        out.append(" (").append(s(a.key));   // piece by piece: see list()
        if (a.value.valid()) out.append(" ").append(expr(a.value));
        out.append(")");
      }
      out += ")";
    }
    return out + ")";
  }
  std::string node(const DeleteStmt& n) {
    static constexpr std::string_view kNames[] = {"Variable", "Variables", "Model",  "Physicals",
                                                  "Meshes",   "All",       "Options"};
    return "(delete " + std::string(kNames[static_cast<int>(n.what)]) +
           (n.what == DeleteWhat::Variable ? " " + name(n.name) : "") + ")";
  }
  std::string node(const DeleteFieldStmt& n) { return "(delete-field " + expr(n.id) + ")"; }
  std::string node(const DeleteCoastlineStmt& n) { return "(delete-coastline " + expr(n.id) + ")"; }
  std::string node(const DeleteShapesStmt& n) {
    return std::string(n.recursive ? "(recursive-delete " : "(delete ") + shapes(n.shapes) + ")";
  }
  std::string node(const PrintStmt& n) {
    static constexpr std::string_view kNames[] = {"Printf", "Warning", "Error"};
    std::string out = "(" + std::string(kNames[static_cast<int>(n.kind)]) + " " + expr(n.format) + list(n.args);
    if (n.redirect != Redirect::None) out += std::string(n.redirect == Redirect::Write ? " > " : " >> ") + expr(n.file);
    return out + ")";
  }
  std::string node(const IfStmt& n) {
    std::string out = "(if";
    for (const IfBranch& b : n.branches) out += " (" + expr(b.cond) + " " + body(b.body) + ")";
    if (n.has_else) out += " (else " + body(n.else_body) + ")";
    return out + ")";
  }
  std::string node(const ForStmt& n) {
    return "(for " + s(n.var) + " " + expr(n.from) + " " + expr(n.to) + " " + expr(n.step) + " " + body(n.body) + ")";
  }
  std::string node(const MacroStmt& n) {
    return "(macro " + (n.name.valid() ? s(n.name) : expr(n.name_expr)) + " " + body(n.body) + ")";
  }
  std::string node(const CallStmt& n) {
    return "(call-macro " + (n.name.valid() ? s(n.name) : expr(n.name_expr)) + ")";
  }
  std::string node(const ReturnStmt&) { return "(return)"; }
  std::string node(const ExitStmt& n) { return "(exit" + (n.code.valid() ? " " + expr(n.code) : std::string()) + ")"; }
  std::string node(const AbortStmt&) { return "(abort)"; }
  std::string node(const AssertStmt& n) {
    return "(assert " + expr(n.cond) + " " + expr(n.message) + list(n.args) + ")";
  }
  std::string node(const IncludeStmt& n) { return "(include " + expr(n.path) + ")"; }
  std::string node(const CommandStmt& n) {
    return "(command " + s(n.command) + (n.arg.valid() ? " " + expr(n.arg) : "") + ")";
  }
  std::string node(const SetFactoryStmt& n) { return "(set-factory " + expr(n.name) + ")"; }
  std::string node(const SetMaxTagStmt& n) { return "(set-max-tag " + ent(n.ent) + " " + expr(n.tag) + ")"; }
  std::string node(const PointStmt& n) { return "(point " + expr(n.tag) + " " + expr(n.coords) + ")"; }
  std::string node(const CurveStmt& n) {
    static constexpr std::string_view kNames[] = {"Line",   "Spline",  "BSpline",        "Bezier",         "Nurbs",
                                                  "Circle", "Ellipse", "CompoundSpline", "CompoundBSpline"};
    return "(" + std::string(kNames[static_cast<int>(n.kind)]) + " " + expr(n.tag) + " " + expr(n.points) +
           opt("plane", n.plane) + opt("knots", n.knots) + opt("order", n.order) + opt("using", n.using_n) + ")";
  }
  std::string node(const CurveLoopStmt& n) { return "(curve-loop " + expr(n.tag) + " " + expr(n.curves) + ")"; }
  std::string node(const SurfaceStmt& n) {
    return std::string(n.kind == SurfaceKind::Plane ? "(plane-surface " : "(surface ") + expr(n.tag) + " " +
           expr(n.loops) + opt("in-sphere", n.in_sphere) + ")";
  }
  std::string node(const SurfaceLoopStmt& n) { return "(surface-loop " + expr(n.tag) + " " + expr(n.surfaces) + ")"; }
  std::string node(const VolumeStmt& n) { return "(volume " + expr(n.tag) + " " + expr(n.loops) + ")"; }
  std::string node(const SphereStmt& n) {
    return std::string(n.polar ? "(polar-sphere " : "(sphere ") + expr(n.tag) + " " + expr(n.points) + ")";
  }
  std::string node(const ParametricSurfaceStmt& n) {
    return "(parametric-surface " + expr(n.tag) + " " + expr(n.fx) + " " + expr(n.fy) + " " + expr(n.fz) + ")";
  }
  std::string node(const CoordinatesSurfaceStmt& n) { return "(coordinates-surface " + expr(n.geometry) + ")"; }
  std::string node(const EuclideanCoordinatesStmt&) { return "(euclidean-coordinates)"; }
  std::string node(const PhysicalStmt& n) {
    return "(physical " + ent(n.ent) + " " + expr(n.tag) + " " + expr(n.name) + " " + std::string(affop_text(n.op)) +
           " " + expr(n.entities) + ")";
  }
  std::string node(const CoherenceStmt& n) {
    static constexpr std::string_view kNames[] = {"Geometry", "Mesh", "Points"};
    return "(coherence " + std::string(kNames[static_cast<int>(n.what)]) +
           (n.points.valid() ? " " + expr(n.points) : "") + ")";
  }
  std::string node(const SplitCurveStmt& n) { return "(split-curve " + expr(n.curve) + " " + expr(n.points) + ")"; }
  std::string node(const ShapeExprStmt& n) { return "(shape-stmt " + expr(n.expr) + ")"; }
  std::string node(const EmbedStmt& n) {
    return "(embed " + ent(n.ent) + " " + expr(n.tags) + " " + ent(n.target) + " " + expr(n.target_tag) + ")";
  }
  std::string node(const MeshSizeStmt& n) {
    return "(mesh-size " + std::string(n.all ? ":" : expr(n.points)) + " " + expr(n.size) + ")";
  }
  std::string node(const TransfiniteCurveStmt& n) {
    return "(transfinite-curve " + std::string(n.all ? ":" : expr(n.curves)) + " " + expr(n.nodes) +
           (n.distribution.valid() ? " " + s(n.distribution) + " " + expr(n.coef) : "") + ")";
  }
  std::string node(const TransfiniteSurfaceStmt& n) {
    return "(transfinite-surface " + std::string(n.all ? ":" : expr(n.surfaces)) + " " + expr(n.corners) +
           (n.arrangement.valid() ? " " + s(n.arrangement) : "") + ")";
  }
  std::string node(const RecombineStmt& n) {
    return "(recombine " + ent(n.ent) + " " + (n.all ? ":" : expr(n.tags)) + opt("angle", n.angle) + ")";
  }
  std::string node(const EntitySettingStmt& n) {
    static constexpr std::string_view kNames[] = {"MeshAlgorithm", "MeshSizeFromBoundary", "Smoother"};
    return "(" + std::string(kNames[static_cast<int>(n.kind)]) + " " + ent(n.ent) + " " + (n.all ? ":" : expr(n.tags)) +
           " " + expr(n.value) + ")";
  }
  std::string node(const PeriodicStmt& n) {
    static constexpr std::string_view kTransforms[] = {"", "translate", "rotate", "affine"};
    const std::string slave = n.slave_surface.valid() ? expr(n.slave_surface) + " " : "";
    const std::string master = n.master_surface.valid() ? expr(n.master_surface) + " " : "";
    return "(periodic " + ent(n.ent) + " " + slave + expr(n.slaves) + " " + master + expr(n.masters) +
           (n.transform == PeriodicTransform::None
                ? ""
                : " (" + std::string(kTransforms[static_cast<int>(n.transform)]) + list(n.transform_args) + ")") +
           ")";
  }
  std::string node(const ReverseMeshStmt& n) {
    return "(reverse-mesh " + ent(n.ent) + " " + (n.all ? ":" : expr(n.tags)) + ")";
  }
  std::string node(const CompoundStmt& n) { return "(compound " + ent(n.ent) + " " + expr(n.tags) + ")"; }
  std::string node(const FieldNewStmt& n) { return "(field-new " + expr(n.id) + " " + s(n.type) + ")"; }
  std::string node(const FieldOptionStmt& n) {
    return "(field-option " + expr(n.id) + " " + s(n.option) + " " + expr(n.value) + ")";
  }
  std::string node(const FieldActionStmt& n) { return "(field-action " + expr(n.id) + " " + s(n.action) + ")"; }
  std::string node(const CoastlineNewStmt& n) { return "(coastline-new " + expr(n.id) + " " + s(n.format) + ")"; }
  std::string node(const CoastlineOptionStmt& n) {
    return "(coastline-option " + expr(n.id) + " " + s(n.option) + " " + expr(n.value) + ")";
  }
  std::string node(const CoastlineActionStmt& n) { return "(coastline-action " + expr(n.id) + " " + s(n.action) + ")"; }
  std::string node(const BackgroundFieldStmt& n) { return "(" + s(n.which) + "-field " + expr(n.value) + ")"; }
  std::string node(const PluginStmt& n) {
    return "(plugin " + s(n.plugin) + " " + s(n.member) + (n.value.valid() ? " " + expr(n.value) : "") + ")";
  }
  std::string node(const ViewStmt& n) {
    std::string out = "(view " + expr(n.name);
    for (const ViewItem& it : n.items)
      out += " (" + s(it.type) + " (" + list(it.coords).substr(it.coords.empty() ? 0 : 1) + ")" + list(it.values) + ")";
    return out + ")";
  }
  std::string node(const ColorStmt& n) { return "(color " + expr(n.color) + " " + shapes(n.shapes) + ")"; }
  std::string node(const VisibilityStmt& n) {
    return std::string("(") + (n.recursive ? "recursive-" : "") + (n.show ? "show " : "hide ") +
           (n.pattern.valid() ? expr(n.pattern) : shapes(n.shapes)) + ")";
  }

  const Ast& ast_;
};

}  // namespace

std::string dump_expr(const Ast& ast, ExprId id) { return Dumper(ast).expr(id); }
std::string dump_stmt(const Ast& ast, StmtId id) { return Dumper(ast).stmt(id); }

std::string dump(const Ast& ast, const StmtList& stmts) {
  std::string out;
  Dumper d(ast);
  for (StmtId s : stmts) out += d.stmt(s) + "\n";
  return out;
}

}  // namespace sm::lang
