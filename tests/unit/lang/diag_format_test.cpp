// Typed diagnostic formats: the slots a format reads, and typed reports' text.
#include <doctest/doctest.h>

#include <string>

#include "lang/diag_format.h"
#include "lang/diagnostics.h"
#include "lang/source.h"

using namespace sm::lang;

TEST_CASE("diag_format_arity: automatic and numbered slots, literal braces") {
  static_assert(diag_format_arity("division by zero") == 0);
  static_assert(diag_format_arity("index {} is out of range for '{}' of size {}") == 3);
  static_assert(diag_format_arity("invalid byte 0x{:02X} (binary data)") == 1);
  static_assert(diag_format_arity("Coastline[{0}] is already defined: 'Delete Coastline[{0}];'") == 1);
  static_assert(diag_format_arity("{1} before {0}") == 2);
  static_assert(diag_format_arity("write {{{}}}") == 1);
  static_assert(diag_format_arity("braces {{}} only") == 0);
  CHECK(diag_format_arity("unclosed {") == -1);
  CHECK(diag_format_arity("stray }") == -1);
}

TEST_CASE("diag_format_arity: every kind's format is well formed") {
  for (std::size_t i = 0; i < static_cast<std::size_t>(Diag::kCount); ++i) {
    CAPTURE(diag_info(static_cast<Diag>(i)).kebab);
    CHECK(diag_format_arity(kDiagFormats[i]) >= 0);
    CHECK(kDiagFormats[i] == diag_info(static_cast<Diag>(i)).format);
  }
}

TEST_CASE("typed report: the table's sentence with the values passed") {
  SourceManager sm;
  Diagnostics diags(sm);
  diags.report(SourceRange{}, Diag::IndexOutOfRange, 7, "xs", std::size_t{3});
  diags.report(SourceRange{}, Diag::DuplicateCoastline, 4);
  diags.report(SourceRange{}, Diag::InvalidByte, 0xC3);
  REQUIRE(diags.all().size() == 3);
  CHECK(diags.all()[0].message == "index 7 is out of range for 'xs' of size 3");
  CHECK(diags.all()[1].message == "Coastline[4] is already defined: 'Delete Coastline[4];' first to redefine it");
  CHECK(diags.all()[2].message == "invalid byte 0xC3 (binary data or text that is not UTF-8)");
  CHECK(format_diag<int>(Diag::CallTooDeep, 100) == "macro calls nested deeper than 100 (infinite recursion?)");
}

TEST_CASE("typed report: the field errors' sentences, one kind per shape") {
  CHECK(format_diag<std::string, std::string>(Diag::UnknownFieldKind, "Treshold", " (did you mean 'Threshold'?)") ==
        "unknown field type 'Treshold' (did you mean 'Threshold'?)");
  CHECK(format_diag<int, std::string, int>(Diag::MissingFieldReference, 1, "Threshold", 5) ==
        "Field[1] (Threshold) references Field[5], which is not defined");
  CHECK(format_diag<std::string, int, std::string>(Diag::FieldExpressionError, "x +* 2", 4, "unexpected '*'") ==
        "MathEval expression \"x +* 2\", column 4: unexpected '*'");
  // One kebab name for the family the script tests match on.
  CHECK(diag_info(Diag::MissingFieldReference).kebab == diag_info(Diag::MissingField).kebab);
}

TEST_CASE("typed report: the limits' sentences, one kind per shape") {
  CHECK(format_diag<std::string, std::string, std::string, std::string, std::size_t>(
            Diag::LimitLoopIterations, "1", "1e+09", "1", "1e+09", std::size_t{10000000}) ==
        "loop 1:1e+09:1 would run 1e+09 iterations, more than the limit of 10000000");
  CHECK(format_diag<int, int, int, int>(Diag::LimitFieldNestingPath, 1, 100, 1, 2) ==
        "Field[1] references fields nested deeper than 100 levels (Field[1] -> Field[2] -> ...)");
  CHECK(format_diag<int, double, double>(Diag::LimitCurveNodesBudget, 3, 2.5e7, 1e7) ==
        "curve 3 would get about 2.5e+07 nodes, over Mesh.MaxElements = 1e+07: check the mesh sizes, or raise "
        "Mesh.MaxElements");
  CHECK(format_diag<double, int, double>(Diag::LimitAllCurvesCap, 3.1e9, 4, 2e9) ==
        "the curves would get about 3.1e+09 nodes in all (curve 4 the most), over the 2e+09 nodes a curve can have: "
        "check the mesh sizes");
  CHECK(std::string(diag_info(Diag::LimitSurfaceTriangles).kebab) == "limit-exceeded");
  CHECK(diag_info(Diag::LimitStatements).kebab == diag_info(Diag::LimitRange).kebab);
}

TEST_CASE("typed report: wrong types, list sizes and invalid operations, one kind per shape") {
  CHECK(format_diag<std::string_view>(Diag::TypeExpectedNumber, "a string list") ==
        "expected a number, found a string list");
  CHECK(format_diag<std::string_view, double>(Diag::TypeIdNotInteger, "field", 1e20) ==
        "a field id must be an integer, not 1e+20");
  CHECK(format_diag<std::string_view, std::string_view, std::string_view>(Diag::TypeOperatorOperands, "+", "a string",
                                                                          "a number") ==
        "operator '+' needs numbers, found a string and a number");
  // The braces of the syntax a message names are Gmsh's, once each.
  CHECK(format_diag<std::size_t>(Diag::ListExtrudeParameters, 5) ==
        "Extrude needs {dx, dy, dz}, {{ax, ay, az}, {px, py, pz}, angle} or "
        "{{dx, dy, dz}, {ax, ay, az}, {px, py, pz}, angle}, got 5 numbers");
  CHECK(format_diag<>(Diag::ListLayers) ==
        "Layers needs {n} or {{n1, n2, ...}, {h1, h2, ...}} with as many heights as element counts");
  CHECK(format_diag<>(Diag::ListDilateParameters) == "Dilate needs {{cx, cy, cz}, factor}");
  CHECK(format_diag<const char*, std::size_t>(Diag::ListNeedsOneNumber, "the Rotate angle", 2) ==
        "the Rotate angle needs 1 number, got 2");
  CHECK(format_diag<std::size_t>(Diag::PeriodicRotateArguments, 4) ==
        "'Rotate {{ax, ay, az}, {px, py, pz}, angle}' takes an axis, a point and an angle: found 4 numbers");
  CHECK(format_diag<std::string_view>(Diag::EntityQueryNoValue, "Curve") ==
        "'Curve{t}' has no value: only Point{t} (its coordinates) and Curve{:} (all tags)");
  CHECK(format_diag<double, double>(Diag::LayersElementCount, 2e6, 1e6) ==
        "Layers{2000000}: the number of elements must be below 1000000");
  CHECK(format_diag<std::string_view, std::string>(Diag::OptionOnlyAssign, "box", "Mesh.Region") ==
        "box option 'Mesh.Region' only takes '='");
  CHECK(diag_info(Diag::TypeMixedList).kebab == std::string_view("wrong-type"));
  CHECK(diag_info(Diag::ListOperandSizes).kebab == std::string_view("list-size-mismatch"));
  CHECK(diag_info(Diag::PeriodicEndsMissed).kebab == std::string_view("invalid-operation"));
  CHECK(diag_info(Diag::IncludeCannotOpen).kebab == std::string_view("include-failed"));
  CHECK(diag_info(Diag::ScriptCannotOpen).kebab == std::string_view("cannot-open-file"));
}

TEST_CASE("typed report: the 1D mesh's crossings, by their curves and place") {
  CHECK(format_diag<int, double, double>(Diag::MeshCurveCrossesItself, 3, 10.0000004, -40.25) ==
        "curve 3 intersects itself near lon 10.000000, lat -40.250000");
  CHECK(format_diag<int, int, double, double, double>(Diag::MeshCurvesCrossXyz, 1, 2, 0.5, 1.0, 0.0) ==
        "curves 1 and 2 intersect near (0.5, 1, 0)");
  CHECK(format_diag<int, int, double, double>(Diag::MeshCurvesShareNodePlace, 4, 7, 1.5, 2.5) ==
        "curves 4 and 7 have distinct nodes at the same place near lon 1.500000, lat 2.500000");
  CHECK(diag_info(Diag::MeshCurvesShareNodePlaceXyz).kebab == std::string_view("curves-intersect"));
}

TEST_CASE("typed report: option refusals and the mesh options' checks, all invalid-option-value") {
  CHECK(format_diag<std::size_t>(Diag::OptionColorSize, 5) ==
        "a color is {r, g, b} or {r, g, b, a}, found 5 numbers");
  CHECK(format_diag<std::string, std::size_t>(Diag::OptionBoxSize, "Mesh.PictureBox", 3) ==
        "'Mesh.PictureBox' is a box {west, east, south, north} in degrees, found 3 numbers");
  CHECK(format_diag<std::string, std::string>(Diag::OptionBoxText, "Mesh.PictureBox", "1,2") ==
        "'Mesh.PictureBox' is a box: give four numbers \"west,east,south,north\" in degrees, not '1,2'");
  CHECK(format_diag<std::string, std::string>(Diag::OptionNotKnownDidYouMean, "Mesh.Algorthm", "Mesh.Algorithm") ==
        "unknown option 'Mesh.Algorthm' (did you mean 'Mesh.Algorithm'?)");
  CHECK(format_diag<double>(Diag::PartitionMeshCount, 2.5) ==
        "PartitionMesh 2.5: give a whole number of partitions, 1 or more");
  CHECK(format_diag<double>(Diag::DepthFieldNamesNoField, 7) ==
        "Mesh.DepthField = 7 names no field: define Field[7], or set Mesh.DepthField = 0");
  CHECK(format_diag<int, double, double>(Diag::CoastlineMinTimeStepFieldUndefined, 2, 30, 5) ==
        "Coastline[2]: Mesh.MinTimeStep = 30 closes the passages too narrow for it at their depth, and "
        "Mesh.DepthField = 5 names no field yet: define the depth field and set Mesh.DepthField before this "
        "statement (or set Mesh.MinTimeStep after it)");
  for (Diag d : {Diag::OptionNotKnown, Diag::OptionWrongKind, Diag::OptionValueOutside, Diag::OptionUnknownColorName,
                 Diag::PartitionMeshNoMesh, Diag::RecombinationFullQuad, Diag::PartitionsNeed2dMesh,
                 Diag::MinTimeStepNeedsDepth, Diag::CoastlineMinTimeStepNoDepthField})
    CHECK(diag_info(d).kebab == std::string_view("invalid-option-value"));
}
