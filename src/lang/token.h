// Tokens of the .geo language: a kind plus a byte range into the source. The
// spelled text (e.g. "Line" for Tok::Curve) is always recoverable from the range.
#pragma once

#include <cstdint>
#include <string_view>

#include "lang/source.h"

namespace sm::lang {

// Reserved words: X(Kind, "spelling"). Synonyms map to one kind (Line ≡ Curve,
// CatmullRom ≡ Spline, Ellipsis ≡ Ellipse, Function ≡ Macro, Euclidian ≡ Euclidean,
// Reverse ≡ ReverseMesh); the token's range keeps what the user wrote.
// Contextual words (Include, Save, Mesh, Background, Loop, Run, Using-targets...)
// and built-in function names (Sqrt, StrCat, Min...) are plain Ident tokens.
#define SM_GEO_KEYWORDS(X)                                   \
  X(For, "For") X(In, "In") X(EndFor, "EndFor")              \
  X(If, "If") X(ElseIf, "ElseIf") X(Else, "Else") X(EndIf, "EndIf") \
  X(Macro, "Macro") X(Macro, "Function") X(Return, "Return") X(Call, "Call") \
  X(Exit, "Exit") X(Abort, "Abort") X(Assert, "Assert")      \
  X(Printf, "Printf") X(Warning, "Warning") X(ErrorCmd, "Error") \
  X(DefineConstant, "DefineConstant") X(Delete, "Delete") X(Recursive, "Recursive") \
  X(Physical, "Physical") X(Point, "Point") X(Curve, "Curve") X(Curve, "Line") \
  X(Surface, "Surface") X(Volume, "Volume")                  \
  X(Circle, "Circle") X(Ellipse, "Ellipse") X(Ellipse, "Ellipsis") \
  X(Spline, "Spline") X(Spline, "CatmullRom") X(BSpline, "BSpline") X(Bezier, "Bezier") \
  X(Nurbs, "Nurbs") X(Knots, "Knots") X(Order, "Order") X(Compound, "Compound") \
  X(Plane, "Plane") X(Sphere, "Sphere") X(PolarSphere, "PolarSphere") \
  X(Parametric, "Parametric") X(Coordinates, "Coordinates")  \
  X(Euclidean, "Euclidean") X(Euclidean, "Euclidian")        \
  X(Field, "Field") X(Coastline, "Coastline")                \
  X(Transfinite, "Transfinite") X(Using, "Using") X(Recombine, "Recombine") \
  X(MeshSize, "MeshSize") X(Characteristic, "Characteristic") X(Length, "Length") \
  X(Translate, "Translate") X(Rotate, "Rotate") X(Dilate, "Dilate") \
  X(Symmetry, "Symmetry") X(Duplicata, "Duplicata") X(Extrude, "Extrude") \
  X(Boundary, "Boundary") X(CombinedBoundary, "CombinedBoundary") X(PointsOf, "PointsOf") \
  X(BoundingBox, "BoundingBox") X(Coherence, "Coherence") X(Split, "Split") \
  X(SetFactory, "SetFactory") X(SetMaxTag, "SetMaxTag") X(Periodic, "Periodic") \
  X(ReverseMesh, "ReverseMesh") X(ReverseMesh, "Reverse") X(Smoother, "Smoother") \
  X(MeshAlgorithm, "MeshAlgorithm") X(MeshSizeFromBoundary, "MeshSizeFromBoundary") \
  X(Plugin, "Plugin") X(View, "View") X(Color, "Color") X(Hide, "Hide") X(Show, "Show")

enum class Tok : std::uint8_t {
  Eof,
  Error,   ///< a bad character / byte run (already diagnosed)
  Ident,   ///< [A-Za-z_][A-Za-z0-9_]*
  Number,  ///< 123, 1., .5, 1.5e-3 (no sign)
  String,  ///< "..." or '...' (range includes the quotes; no escapes)
  Constant,  ///< Pi, newp, newreg, GMSH_MAJOR_VERSION, Today, ... (see constant_from_text)
  // punctuation
  LParen, RParen, LBracket, RBracket, LBrace, RBrace,
  Comma, Semicolon, Colon, ColonColon, Dot, Hash, Tilde, Question,
  Plus, Minus, Star, Slash, Percent, Caret, Not, Amp, Pipe,
  AmpAmp, PipePipe, Less, Greater, LessEq, GreaterEq, EqEq, NotEq, ShiftLeft, ShiftRight,
  PlusPlus, MinusMinus,
  Assign, PlusAssign, MinusAssign, StarAssign, SlashAssign,
  // keywords
  For, In, EndFor, If, ElseIf, Else, EndIf, Macro, Return, Call, Exit, Abort, Assert,
  Printf, Warning, ErrorCmd, DefineConstant, Delete, Recursive, Physical, Point, Curve,
  Surface, Volume, Circle, Ellipse, Spline, BSpline, Bezier, Nurbs, Knots, Order, Compound,
  Plane, Sphere, PolarSphere, Parametric, Coordinates, Euclidean, Field, Coastline,
  Transfinite, Using, Recombine, MeshSize, Characteristic, Length, Translate, Rotate,
  Dilate, Symmetry, Duplicata, Extrude, Boundary, CombinedBoundary, PointsOf, BoundingBox,
  Coherence, Split, SetFactory, SetMaxTag, Periodic, ReverseMesh, Smoother, MeshAlgorithm,
  MeshSizeFromBoundary, Plugin, View, Color, Hide, Show,
  kCount
};

struct Token {
  Tok kind = Tok::Eof;
  SourceRange range;
};

/// How a kind is named in messages: "';'", "identifier", "'For'", "end of file".
std::string_view tok_name(Tok kind);
/// The reserved word spelled `text`, or Tok::Ident when it is not one.
Tok keyword_from_text(std::string_view text);
bool is_keyword(Tok kind);

}  // namespace sm::lang
