// The syntax tree of a .geo script: expression and statement nodes in flat arrays
// owned by Ast, addressed by ExprId/StmtId, each with its SourceRange. Loops and
// macros re-evaluate these nodes; the text is never re-read (grammar/geo.ebnf).
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

#include "base/id.h"
#include "lang/builtin_function.h"
#include "lang/source.h"
#include "lang/token.h"

namespace sm::lang {

using ExprId = Id<struct ExprTag>;
using StmtId = Id<struct StmtTag>;
using StrId = Id<struct StrTag>;  ///< interned text (identifiers, string literals)
using ExprList = std::vector<ExprId>;
using StmtList = std::vector<StmtId>;

enum class EntityKind : std::uint8_t { Point, Curve, Surface, Volume };
std::string_view entity_name(EntityKind e);  // "Point", "Curve", ...

/// Assignment operators: = += -= *= /=.
enum class AffOp : std::uint8_t { Assign, Add, Sub, Mul, Div };
std::string_view affop_text(AffOp op);  // "=", "+=", ...

/// A variable name: `x`, `x~{i}~{j}` (evaluates to "x_<int i>_<int j>"), or
/// `StringToName["s"]` / `S2N[...]` (the name is the string's value).
struct Name {
  StrId ident;           ///< base identifier; invalid for the StringToName form
  ExprList suffixes;     ///< the `~{expr}` parts, in order
  ExprId from_string;    ///< StringToName form: a string expression; else invalid
  SourceRange range;
};

/// An option reference `Cat.Member`, `Cat[idx].Member`, `Cat.Color.Name`.
/// Any word, keywords included, may be a member (`Mesh.Smoothing`, `Field`...).
struct OptionRef {
  StrId category;        ///< "Mesh", "General", "Geometry", "View", ...
  ExprId index;          ///< `View[0].Name`: the index; else invalid
  StrId member;          ///< "Algorithm"; "Color" for the color form
  StrId sub_member;      ///< `Geometry.Color.Points`: "Points"; else invalid
  SourceRange range;
};

// ---------------------------------------------------------------- shapes

/// One entry of a shape block `{ Point{1,2}; Physical Curve{3}; Line(5)={1,2}; }`
/// or the body of a transform.
struct ShapeItem {
  enum class Kind : std::uint8_t {
    Entities,  ///< `Point{items};` (physical: `Physical Curve{items};`, all: `Curve{:};`)
    Create,    ///< a creation statement run inside the block; its new entity is a shape
    Nested,    ///< a transform/Duplicata expression whose result is the block's shapes
  };
  Kind kind = Kind::Entities;
  EntityKind ent = EntityKind::Point;  ///< Entities
  bool physical = false;               ///< Entities: `Physical <ent>{...}`
  bool all = false;                    ///< Entities: `<ent>{:}`
  ExprList tags;                       ///< Entities: the items (ranges/lists allowed)
  StmtId create;                       ///< Create
  ExprId nested;                       ///< Nested: a TransformExpr
  SourceRange range;
};
using ShapeBlock = std::vector<ShapeItem>;

// ---------------------------------------------------------------- expressions
// A list-valued expression may appear wherever a value is expected: the
// evaluator flattens ListExpr/RangeExpr items, broadcasts scalar operators over
// lists (`-{...}`, `k*{...}`), and takes element 0 of a list used as a scalar.

struct ErrorExpr {};  ///< placeholder after a syntax error (never evaluated)
struct NumberExpr { double value = 0; };
struct StringExpr { StrId text; };  ///< raw text without the quotes; no escapes (Gmsh)
struct VarExpr { Name name; };      ///< a variable (scalar, list: element 0 as scalar, or string)

/// Built-in constants (lexer-level in Gmsh): Pi, newp, ..., Today.
enum class Constant : std::uint8_t {
  Pi, NewP, NewL, NewC, NewLL, NewCL, NewS, NewSL, NewV, NewReg, NewF,
  GmshMajorVersion, GmshMinorVersion, GmshPatchVersion, MpiSize, MpiRank,
  Cpu, Memory, TotalMemory,
  // string-valued
  Today, CurrentDirectory, CurrentFileName, GmshExecutableName, OnelabAction,
  kCount
};
/// Constant spelled `text` (also `CurrentDir`), or Constant::kCount.
Constant constant_from_text(std::string_view text);
std::string_view constant_text(Constant c);
bool constant_is_string(Constant c);
struct ConstantExpr { Constant which = Constant::Pi; };

/// `-a`, `+a`, `!a`. op is Tok::Minus, Tok::Plus or Tok::Not.
struct UnaryExpr { Tok op = Tok::Minus; ExprId operand; };
/// `a op b`, op one of: ^ * / % | & + - < > <= >= << >> == != && ||
/// (Tok::Caret ... Tok::PipePipe). && and || evaluate both sides (Gmsh).
struct BinaryExpr { Tok op = Tok::Plus; ExprId lhs, rhs; };
/// `c ? a : b`
struct TernaryExpr { ExprId cond, then_expr, else_expr; };
/// `x++` / `x--` used as an expression: returns the old value and updates the
/// variable. target is a VarExpr, IndexExpr or OptionExpr. op: PlusPlus/MinusMinus.
struct PostfixExpr { Tok op = Tok::PlusPlus; ExprId target; };
/// `a[i]` or `a(i)`: element i (truncated to int, from 0).
struct IndexExpr { Name name; ExprId index; bool paren = false; };
/// `a[]` or `a()`: the whole list (a scalar gives a 1-item list).
struct WholeListExpr { Name name; bool paren = false; };
/// `a[{items}]` / `a({items})`: the sub-list at those indices.
struct SliceExpr { Name name; ExprList indices; bool paren = false; };
/// `#a[]` / `#a()`: list length. `list` is the operand (a WholeListExpr, or any
/// list expression such as `#{1,2}` / `#Point{:}`... in the native extension).
struct LengthExpr { ExprId list; };
/// `{items}`: items may be ranges, lists (flattened), strings (string lists).
struct ListExpr { ExprList items; };
/// `from:to` or `from:to:step` (step invalid when absent: ±1 by direction).
struct RangeExpr { ExprId from, to, step; };
/// `Func(args)` / `Func[args]` for a built-in function name (the rows of
/// lang/builtin_functions.def): math (Sqrt, Atan2, Min...), strings (StrCat,
/// Sprintf, StrSub...), lists (Unique, LinSpace, List...), queries (Exists,
/// GetNumber, FileExists...). Args are as written; the table's BuiltinPass
/// says which are names (Exists(x), NameToString[x]), strings or lists.
struct CallExpr {
  StrId func;
  SourceRange func_range;
  ExprList args;
  bool square = false;
  BuiltinId fn = BuiltinId::kNone;   ///< the table row of `func`
};
/// Reading an option: `Mesh.Algorithm`, `View[0].Name`, `General.Color.Text`.
struct OptionExpr { OptionRef option; };
/// `Point{t}` (coordinates), `Curve{:}` (all tags), `Physical Surface{t}`
/// (members of group t; in string context `Physical Curve{t}` is the name).
struct EntityQueryExpr { EntityKind ent = EntityKind::Point; bool physical = false; bool all = false; ExprList tags; };
/// `Point In BoundingBox{xmin,ymin,zmin,xmax,ymax,zmax}`: tags inside the box.
struct EntityInBoxExpr { EntityKind ent = EntityKind::Point; ExprList box; };
/// `Intersect Curve{curves} Surface{s}`: a new point where each curve meets the surface.
struct IntersectExpr { ExprList curves; ExprId surface; };
enum class BoundaryKind : std::uint8_t { Boundary, CombinedBoundary, PointsOf };
/// `Boundary{ Surface{1}; }` etc.: signed tags of the boundary entities.
struct BoundaryExpr { BoundaryKind kind = BoundaryKind::Boundary; ShapeBlock shapes; };
enum class TransformKind : std::uint8_t { Translate, Rotate, Symmetry, Dilate, Duplicata, Extrude };
/// `Translate{dx,dy,dz}{shapes}`, `Rotate{{ax,ay,az},{px,py,pz},angle}{shapes}`,
/// `Symmetry{a,b,c,d}{shapes}`, `Dilate{{cx,cy,cz},f}{shapes}` (f may be {fx,fy,fz}),
/// `Duplicata{shapes}`. params are the items of the first braces as written
/// (Rotate: [ListExpr axis, ListExpr point, angle]; Duplicata: empty).
/// Result: the new/moved entity tags (Gmsh returns them as a list).
/// `Extrude {dx,dy,dz} | {{axis},{point},angle} | {{dx,dy,dz},{axis},{point},angle} {shapes
/// [Layers{n}; | Layers{{n..},{h..}}; Recombine [expr]; ScaleLast; QuadTri...;]}`: params as
/// written, layers the items of Layers' braces (empty: no Layers), recombine invalid
/// without `Recombine` (a NumberExpr 1 when written bare). See docs/interpreter.md.
struct ExtrudeMeshParams { ExprList layers; SourceRange layers_range; bool has_recombine = false; ExprId recombine; };
struct TransformExpr {
  TransformKind kind = TransformKind::Translate;
  ExprList params;
  ShapeBlock shapes;
  ExtrudeMeshParams extrude;
};
/// Native extension: `Coastline{n, ...}` imports coastline object(s) n and
/// returns the new curve-loop tags (outer loop first).
struct CoastlineQueryExpr { ExprList ids; };

// Keep in the order of ExprNode's alternatives.
enum class ExprKind : std::uint8_t {
  Error, Number, String, Var, Constant, Unary, Binary, Ternary, Postfix, Index, WholeList,
  Slice, Length, List, Range, Call, Option, EntityQuery, EntityInBox, Boundary, Transform,
  CoastlineQuery, Intersect
};
using ExprNode = std::variant<ErrorExpr, NumberExpr, StringExpr, VarExpr, ConstantExpr, UnaryExpr,
                              BinaryExpr, TernaryExpr, PostfixExpr, IndexExpr, WholeListExpr,
                              SliceExpr, LengthExpr, ListExpr, RangeExpr, CallExpr, OptionExpr,
                              EntityQueryExpr, EntityInBoxExpr, BoundaryExpr, TransformExpr,
                              CoastlineQueryExpr, IntersectExpr>;

struct Expr {
  SourceRange range;
  ExprNode node;
  ExprKind kind() const { return static_cast<ExprKind>(node.index()); }
};

// ---------------------------------------------------------------- statements
// Entity lists in statements (`{1,2}`, `{1:4}`, a bare `3`) are one ExprId:
// usually a ListExpr; the evaluator flattens. `all` marks the `{:}` form.

/// The left side of an assignment.
struct LValue {
  enum class Kind : std::uint8_t {
    Var,        ///< `x = ...` (list if the right side has 0 or >1 items)
    WholeList,  ///< `L[] = ...` / `L() = ...`
    Element,    ///< `L[i] = ...` (grows the list with 0s)
    SubList,    ///< `L[{i,j}] = {a,b}` (element-wise)
    Option,     ///< `Mesh.Algorithm = ...`, `View[0].Name = ...`, `General.Color.Text = ...`
  };
  Kind kind = Kind::Var;
  Name name;          ///< all but Option
  ExprId index;       ///< Element
  ExprList indices;   ///< SubList
  OptionRef option;   ///< Option
  bool paren = false; ///< written with () instead of []
  SourceRange range;
};

/// `target op value;` value may be a number/string expression, a ListExpr,
/// a RangeExpr, a call (Str(...), Unique(...)), a Boundary/Transform/query.
struct AssignStmt { LValue target; AffOp op = AffOp::Assign; ExprId value; };
/// `x++;` `x--;` `L[2]++;` `Mesh.Smoothing++;`
struct IncDecStmt { LValue target; bool increment = true; };

/// One ONELAB attribute inside DefineConstant braces: `Name "x"`, `Min 0`,
/// `Choices{0,1}`, `ReadOnly` (value invalid). Accepted and ignored by Gmsh-compatible runs.
struct OnelabAttr { StrId key; ExprId value; SourceRange range; };
/// `name`, `name = value`, or `name = {value, attr, attr...}`. value invalid:
/// defaults to 0. value may be a string expression (string constant).
struct DefineEntry { Name name; ExprId value; bool braced = false; std::vector<OnelabAttr> attrs; SourceRange range; };
/// `DefineConstant[ entries ];` assigns only names that are not yet defined.
struct DefineConstantStmt { std::vector<DefineEntry> entries; };

enum class DeleteWhat : std::uint8_t { Variable, Variables, Model, Physicals, Meshes, All, Options };
/// `Delete x;` (Variable: name), `Delete Variables;`, `Delete Model;` ...
struct DeleteStmt { DeleteWhat what = DeleteWhat::Variable; Name name; };
/// `Delete Field[n];`
struct DeleteFieldStmt { ExprId id; };
/// Native `Delete Coastline[n];`
struct DeleteCoastlineStmt { ExprId id; };
/// `Delete { shapes }` / `Recursive Delete { shapes }`
struct DeleteShapesStmt { bool recursive = false; ShapeBlock shapes; };

enum class PrintKind : std::uint8_t { Printf, Warning, Error };
enum class Redirect : std::uint8_t { None, Write, Append };  ///< `> file`, `>> file`
/// `Printf(format, args...) [> file | >> file];` args are items without braces
/// (expressions, ranges, whole lists) as written.
struct PrintStmt {
  PrintKind kind = PrintKind::Printf;
  ExprId format;
  ExprList args;
  Redirect redirect = Redirect::None;
  ExprId file;
};

struct IfBranch { ExprId cond; StmtList body; SourceRange keyword; };  ///< If / ElseIf
/// `If (c) ... ElseIf (c) ... Else ... EndIf`: the first true branch runs, else else_body.
struct IfStmt { std::vector<IfBranch> branches; bool has_else = false; SourceRange else_keyword; StmtList else_body; };
/// `For (from:to[:step]) ... EndFor` (var invalid) or `For var In {from:to[:step]} ... EndFor`.
/// Bounds are evaluated once (Gmsh); see docs/language.md for the loop rules.
struct ForStmt { StrId var; SourceRange var_range; ExprId from, to, step; StmtList body; };
/// `Macro Name ... Return` / `Function Name ...` / `Macro "Name" ...`: name is the
/// identifier or literal; name_expr a non-literal string expression (else invalid).
struct MacroStmt { StrId name; ExprId name_expr; StmtList body; };
/// `Call Name;` / `Call "Name";` / `Call StrCat(...);` (same name/name_expr rule).
struct CallStmt { StrId name; ExprId name_expr; };
/// `Return` nested in an If/For inside a macro body: leaves the macro early.
/// (The Return that closes a Macro is not a node.)
struct ReturnStmt {};
struct ExitStmt { ExprId code; };  ///< `Exit;` (code invalid) / `Exit n;`
struct AbortStmt {};
/// Native extension `Assert(cond, "message"[, args...]);`: message and args as in Printf.
struct AssertStmt { ExprId cond; ExprId message; ExprList args; };
/// `Include "file";` (relative to the including file, then the search path).
struct IncludeStmt { ExprId path; };
/// `IDENT [arg];` commands: Merge, Save, Print, SystemCall, CreateDir, OptimizeMesh,
/// SetName (string arg); Mesh, SetOrder, Sleep, PartitionMesh (number arg);
/// RefineMesh, RecombineMesh, RenumberMeshNodes, RenumberMeshElements, SyncModel,
/// BoundingBox (no arg: arg invalid). The interpreter dispatches on `command`.
struct CommandStmt { StrId command; SourceRange command_range; ExprId arg; };
struct SetFactoryStmt { ExprId name; };  ///< `SetFactory("Built-in");`
struct SetMaxTagStmt { EntityKind ent = EntityKind::Point; ExprId tag; };

/// `Point(tag) = {x, y, z[, lc]};` coords: the ListExpr as written.
struct PointStmt { ExprId tag; ExprId coords; };
enum class CurveKind : std::uint8_t {
  Line,
  Spline,
  BSpline,
  Bezier,
  Nurbs,
  Circle,
  Ellipse,
  CompoundSpline,
  CompoundBSpline
};
/// `Line|Spline|CatmullRom|BSpline|Bezier|Circle|Ellipse(tag) = {points}`;
/// Circle/Ellipse: `Plane{nx,ny,nz}` in plane (ListExpr, else invalid);
/// `Nurbs(t) = {pts} Knots {knots} Order k`; `Compound Spline(t) = {curves} Using n`.
struct CurveStmt {
  CurveKind kind = CurveKind::Line;
  ExprId tag;
  ExprId points;
  ExprId plane;
  ExprId knots;
  ExprId order;
  ExprId using_n;
};
/// `Curve Loop(tag) = {curves};` / `Line Loop`. The second word is not checked (Gmsh).
struct CurveLoopStmt { ExprId tag; ExprId curves; };
enum class SurfaceKind : std::uint8_t { Plane, Filling };
/// `Plane Surface(t) = {loops};` / `Surface(t) = {loop} [In Sphere{center}];`
struct SurfaceStmt { SurfaceKind kind = SurfaceKind::Plane; ExprId tag; ExprId loops; ExprId in_sphere; };
/// `Surface Loop(t) = {surfaces};`
struct SurfaceLoopStmt { ExprId tag; ExprId surfaces; };
/// `Volume(t) = {surface loops};`
struct VolumeStmt { ExprId tag; ExprId loops; };
/// `PolarSphere(g) = {center, point};` / `Sphere(g) = {center, point};`
struct SphereStmt { bool polar = false; ExprId tag; ExprId points; };
/// `Parametric Surface(g) = "fx" "fy" "fz";`
struct ParametricSurfaceStmt { ExprId tag; ExprId fx, fy, fz; };
/// `Coordinates Surface g;`
struct CoordinatesSurfaceStmt { ExprId geometry; };
/// `Euclidean Coordinates;` / `Euclidian Coordinates;`
struct EuclideanCoordinatesStmt {};
/// `Physical <ent>(tag | "name" | "name", tag) (=|+=|-=) {entities};`
/// tag and name each invalid when absent.
struct PhysicalStmt {
  EntityKind ent = EntityKind::Point;
  ExprId tag;
  ExprId name;
  AffOp op = AffOp::Assign;
  ExprId entities;
};
enum class CoherenceKind : std::uint8_t { Geometry, Mesh, Points };
/// `Coherence;` `Coherence Geometry;` `Coherence Mesh;` `Coherence Point{items};`
struct CoherenceStmt { CoherenceKind what = CoherenceKind::Geometry; ExprId points; };
/// `Split Curve{c} Point{points};`
struct SplitCurveStmt { ExprId curve; ExprId points; };
/// A transform/Duplicata/Boundary used as a statement: `Translate{1,0,0}{ Point{1}; };`
struct ShapeExprStmt { ExprId expr; };
/// `Point{tags} In Surface{s};` / `Curve{tags} In Surface{s};`
struct EmbedStmt {
  EntityKind ent = EntityKind::Point;
  ExprId tags;
  EntityKind target = EntityKind::Surface;
  ExprId target_tag;
};
/// `MeshSize{points} = size;` / `Characteristic Length{...} = size;`
struct MeshSizeStmt { bool all = false; ExprId points; ExprId size; };
/// `Transfinite Curve{curves} = nodes [Using Progression|Bump|Beta coef];`
struct TransfiniteCurveStmt { bool all = false; ExprId curves; ExprId nodes; StrId distribution; ExprId coef; };
/// `Transfinite Surface{s} [= {corners}] [Left|Right|Alternate|...];`
struct TransfiniteSurfaceStmt { bool all = false; ExprId surfaces; ExprId corners; StrId arrangement; };
/// `Recombine Surface{tags} [= angle];`
struct RecombineStmt { EntityKind ent = EntityKind::Surface; bool all = false; ExprId tags; ExprId angle; };
enum class SettingKind : std::uint8_t { MeshAlgorithm, MeshSizeFromBoundary, Smoother };
/// `MeshAlgorithm Surface{tags} = v;` `MeshSizeFromBoundary Surface{...} = v;` `Smoother Surface{...} = v;`
struct EntitySettingStmt {
  SettingKind kind = SettingKind::MeshAlgorithm;
  EntityKind ent = EntityKind::Surface;
  bool all = false;
  ExprId tags;
  ExprId value;
};
enum class PeriodicTransform : std::uint8_t { None, Translate, Rotate, Affine };
/// `Periodic Curve{slaves} = {masters} [Translate{dx,dy,dz} | Rotate{{axis},{point},angle} | Affine{16 numbers}];`
/// (transform_args: the transform's items, empty without one), and Gmsh's surface form
/// `Periodic Surface s {slave curves} = m {master curves};` (slave_surface/master_surface set,
/// slaves/masters the curve lists).
struct PeriodicStmt {
  EntityKind ent = EntityKind::Curve;
  ExprId slaves;
  ExprId masters;
  PeriodicTransform transform = PeriodicTransform::None;
  ExprList transform_args;
  ExprId slave_surface;
  ExprId master_surface;
};
/// `ReverseMesh Curve{tags};` / `Reverse Surface{...};`
struct ReverseMeshStmt { EntityKind ent = EntityKind::Curve; bool all = false; ExprId tags; };
/// `Compound Curve{tags};` / `Compound Surface{tags};` (meshing constraint)
struct CompoundStmt { EntityKind ent = EntityKind::Curve; ExprId tags; };

/// `Field[id] = Type;`
struct FieldNewStmt { ExprId id; StrId type; SourceRange type_range; };
/// `Field[id].Option = value;` value: number/string expression, or a ListExpr
/// when written in braces (braced = true; Gmsh ignores a bare value for lists).
struct FieldOptionStmt { ExprId id; StrId option; SourceRange option_range; ExprId value; bool braced = false; };
/// `Field[id].Action;` (a callback, e.g. `Field[1].Run;`)
struct FieldActionStmt { ExprId id; StrId action; SourceRange action_range; };
/// Native `Coastline[id] = Format;` (GSHHS, Shapefile, LonLatText, Loops2): written like a field.
struct CoastlineNewStmt { ExprId id; StrId format; SourceRange format_range; };
/// Native `Coastline[id].Option = value;` (value as in FieldOptionStmt).
struct CoastlineOptionStmt { ExprId id; StrId option; SourceRange option_range; ExprId value; bool braced = false; };
/// Native `Coastline[id].Word;` (no coastline has an action: always an error).
struct CoastlineActionStmt { ExprId id; StrId action; SourceRange action_range; };
/// `Background Field = n;` / `BoundaryLayer Field = n;` (which: the first word)
struct BackgroundFieldStmt { StrId which; ExprId value; };
/// `Plugin(Name).Option = value;` / `Plugin(Name).Run;` (value invalid: an action)
struct PluginStmt { StrId plugin; StrId member; SourceRange member_range; ExprId value; };
/// One post-processing element `T2(coords){values};` `SP(coords){values};` in a View block.
struct ViewItem { StrId type; ExprList coords; ExprList values; SourceRange range; };
/// `View "name" { items };` (post-processing; parsed so that scripts such as t4 load)
struct ViewStmt { ExprId name; std::vector<ViewItem> items; };
/// `Color name|{r,g,b} { shapes }` (display only)
struct ColorStmt { ExprId color; ShapeBlock shapes; };
/// `Hide { shapes }`, `Show "*";`, `Recursive Show { shapes }` (display only)
struct VisibilityStmt { bool show = false; bool recursive = false; ExprId pattern; ShapeBlock shapes; };

// Keep in the order of StmtNode's alternatives.
enum class StmtKind : std::uint8_t {
  Assign, IncDec, DefineConstant, Delete, DeleteField, DeleteCoastline, DeleteShapes, Print, If, For, Macro,
  Call, Return, Exit, Abort, Assert, Include, Command, SetFactory, SetMaxTag, Point, Curve,
  CurveLoop, Surface, SurfaceLoop, Volume, Sphere, ParametricSurface, CoordinatesSurface,
  EuclideanCoordinates, Physical, Coherence, SplitCurve, ShapeExpr, Embed, MeshSize,
  TransfiniteCurve, TransfiniteSurface, Recombine, EntitySetting, Periodic, ReverseMesh,
  Compound, FieldNew, FieldOption, FieldAction, CoastlineNew, CoastlineOption, CoastlineAction,
  BackgroundField, Plugin, View, Color, Visibility
};
using StmtNode =
    std::variant<AssignStmt, IncDecStmt, DefineConstantStmt, DeleteStmt, DeleteFieldStmt, DeleteCoastlineStmt,
                 DeleteShapesStmt, PrintStmt, IfStmt, ForStmt, MacroStmt, CallStmt, ReturnStmt, ExitStmt, AbortStmt,
                 AssertStmt, IncludeStmt, CommandStmt, SetFactoryStmt, SetMaxTagStmt, PointStmt, CurveStmt,
                 CurveLoopStmt, SurfaceStmt, SurfaceLoopStmt, VolumeStmt, SphereStmt, ParametricSurfaceStmt,
                 CoordinatesSurfaceStmt, EuclideanCoordinatesStmt, PhysicalStmt, CoherenceStmt, SplitCurveStmt,
                 ShapeExprStmt, EmbedStmt, MeshSizeStmt, TransfiniteCurveStmt, TransfiniteSurfaceStmt, RecombineStmt,
                 EntitySettingStmt, PeriodicStmt, ReverseMeshStmt, CompoundStmt, FieldNewStmt, FieldOptionStmt,
                 FieldActionStmt, CoastlineNewStmt, CoastlineOptionStmt, CoastlineActionStmt, BackgroundFieldStmt,
                 PluginStmt, ViewStmt, ColorStmt, VisibilityStmt>;

struct Stmt {
  SourceRange range;    ///< the whole statement (for a block: keyword to End keyword)
  SourceRange keyword;  ///< the leading keyword(s) as written ("For", "Line Loop"), for notes
  StmtNode node;
  StmtKind kind() const { return static_cast<StmtKind>(node.index()); }
};

/// Owns every node of every file parsed in a run (Included files and macro
/// bodies share it, so a macro defined in an included file stays callable).
/// Ids are stable: adding nodes never invalidates existing ids.
class Ast {
 public:
  ExprId add_expr(SourceRange range, ExprNode node);
  StmtId add_stmt(SourceRange range, SourceRange keyword, StmtNode node);

  const Expr& expr(ExprId id) const { return exprs_[id.value]; }
  const Stmt& stmt(StmtId id) const { return stmts_[id.value]; }
  Expr& expr_mut(ExprId id) { return exprs_[id.value]; }
  std::size_t expr_count() const { return exprs_.size(); }
  std::size_t stmt_count() const { return stmts_.size(); }

  /// Interns text; equal texts get equal ids (compare ids, not strings).
  StrId intern(std::string_view text);
  std::string_view str(StrId id) const { return strings_[id.value]; }
  /// The id of already interned text, or invalid.
  StrId find(std::string_view text) const;

 private:
  // Deques: the interpreter parses an Included file while it is still running
  // statements of the including one, so node references must survive growth.
  std::deque<Expr> exprs_;
  std::deque<Stmt> stmts_;
  std::deque<std::string> strings_;  // deque: views into it stay valid as it grows
  std::unordered_map<std::string_view, StrId> string_ids_;
};

/// S-expression text of a node, for tests and debugging, e.g.
/// `(assign = (var x) (binary + (num 1) (num 2)))`.
std::string dump_expr(const Ast& ast, ExprId id);
std::string dump_stmt(const Ast& ast, StmtId id);
/// One line per statement.
std::string dump(const Ast& ast, const StmtList& stmts);

}  // namespace sm::lang
