// Field statements from the interpreter's side: the model -> BuildContext
// glue, Mesh.MeshSize* -> SizePolicyOptions, the Background Field the mesher
// asks for, and the exact text of located field diagnostics.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include "interp/kernel/field_context.h"
#include "interp/kernel/field_eval.h"
#include "interp/kernel/size_policy_from_options.h"
#include "interp_test_util.h"

using namespace sm;
using namespace sm::interp;

TEST_CASE("fields: Gmsh's curve samples, point positions and bbox from the model") {
  geo::Model m;
  field::BuildContext empty = make_build_context(m);
  CHECK(empty.bbox_diag == 1);   // CTX::lc of an empty model
  REQUIRE(m.add_point(1, Vec3{0, 0, 0}).ok());
  REQUIRE(m.add_point(2, Vec3{3, 4, 0}).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  const field::BuildContext ctx = make_build_context(m);
  CHECK(ctx.bbox_diag == doctest::Approx(5));
  REQUIRE(ctx.point_position(2).has_value());
  CHECK(ctx.point_position(2)->y == 4);
  CHECK_FALSE(ctx.point_position(9).has_value());
  const auto s = ctx.curve_samples(1, 6);   // t = 1/5 .. 4/5: end points excluded
  REQUIRE(s.has_value());
  REQUIRE(s->size() == 4);
  CHECK((*s)[0].x == doctest::Approx(0.6));
  CHECK((*s)[3].y == doctest::Approx(3.2));
  CHECK(ctx.curve_samples(-1, 6)->size() == 4);
  CHECK(ctx.curve_samples(1, 2)->empty());
  CHECK_FALSE(ctx.curve_samples(7, 6).has_value());
  CHECK_FALSE(ctx.surface_samples);   // Distance reports SurfacesList as not sampleable

  // A meshed curve (2D meshing): its m interior nodes, then K - 2 uniform
  // points with K = N - m (Gmsh 4.8.4's Distance).
  const CurveMeshNodes nodes = {{1, {Vec3{0.3, 0.4, 0}, Vec3{1.5, 2, 0}, Vec3{2.7, 3.6, 0}}}};
  const field::BuildContext meshed = make_build_context(m, {}, &nodes);
  const auto t = meshed.curve_samples(-1, 10);   // K = 7: t = 1/6 .. 5/6
  REQUIRE(t.has_value());
  REQUIRE(t->size() == 8);
  CHECK((*t)[0].x == 0.3);
  CHECK((*t)[3].x == doctest::Approx(3.0 / 6));
  CHECK((*t)[7].y == doctest::Approx(4.0 * 5 / 6));
  CHECK(meshed.curve_samples(1, 4)->size() == 3);   // K = 1: the nodes only
}

TEST_CASE("fields: Mesh.MeshSize* and CharacteristicLength* reach SizePolicyOptions") {
  Options o;
  field::SizePolicyOptions d = size_policy_from_options(o);
  CHECK(d.factor == 1);
  CHECK(d.min == 0);
  CHECK(d.max == 1e22);
  CHECK(d.from_points);
  CHECK(d.extend_from_boundary == 1);
  CHECK(d.from_curvature == 0);
  CHECK(o.set_number("Mesh.CharacteristicLengthMin", 0.5).empty());
  CHECK(o.set_number("Mesh.MeshSizeMax", 2).empty());
  CHECK(o.set_number("Mesh.CharacteristicLengthFactor", 3).empty());
  CHECK(o.set_number("Mesh.MeshSizeFromPoints", 0).empty());
  CHECK(o.set_number("Mesh.CharacteristicLengthExtendFromBoundary", 0).empty());
  CHECK(o.set_number("Mesh.MeshSizeFromCurvature", 12).empty());
  const field::SizePolicyOptions p = size_policy_from_options(o);
  CHECK(p.min == 0.5);
  CHECK(p.max == 2);
  CHECK(p.factor == 3);
  CHECK_FALSE(p.from_points);
  CHECK(p.extend_from_boundary == 0);
  CHECK(p.from_curvature == 12);
  // The combination the mesher will run: the background value clamped to [min, max], times factor.
  field::SizeQuery q;
  q.bbox_diag = 10;
  q.background = 0.1;
  CHECK(field::final_size(p, q).size == doctest::Approx(1.5));
}

namespace {

struct Run {
  lang::SourceManager sources;
  lang::Diagnostics diags{sources};
  std::ostringstream out;
  Interpreter in{sources, diags, out};
};

}  // namespace

TEST_CASE("fields: the Background Field for the mesher") {
  Run r;
  r.in.run_buffer("bg.geo",
                  "Field[1] = MathEval; Field[1].F = \"x + 1\";\n"
                  "Field[2] = Min; Field[2].FieldsList = {1};\n");
  CHECK(background_size_field(r.in) == nullptr);   // no Background Field statement
  r.in.run_buffer("bg2.geo", "Background Field = 2;\n");
  const field::FieldPtr f = background_size_field(r.in);
  REQUIRE(f);
  const Vec3 p{2, 0, 0};
  double h = 0;
  f->eval(std::span<const Vec3>(&p, 1), std::span<double>(&h, 1));
  CHECK(h == 3);
  r.in.run_buffer("bg3.geo", "Background Field = 0;\n");   // Gmsh: ids <= 0 mean none
  CHECK(background_size_field(r.in) == nullptr);
}

TEST_CASE("fields: a missing background field or a cycle is located at Background Field") {
  Run r;
  r.in.run_buffer("bg.geo",
                  "Field[1] = Min;\n"
                  "Field[2] = Threshold;\n"
                  "Field[1].FieldsList = {2};\n"
                  "Field[2].InField = 1;\n"
                  "Background Field = 1;\n");
  REQUIRE(r.diags.error_count() == 0);
  try {
    background_size_field(r.in);
    FAIL("expected a cycle error");
  } catch (const RuntimeError& e) {
    CHECK(e.kind == lang::Diag::FieldCycle);
    CHECK(e.message == "fields reference each other in a cycle: Field[1] -> Field[2] -> Field[1]");
    CHECK(r.sources.line_col(e.range.begin_loc()).line == 5);
    REQUIRE(e.notes.size() >= 2);
    CHECK(e.notes[0].message == "Field[1] (Min) reads Field[2] here");
    CHECK(r.sources.line_col(e.notes[0].range.begin_loc()).line == 3);
    CHECK(e.notes[1].message == "Field[2] (Threshold) reads Field[1] here");
    CHECK(r.sources.line_col(e.notes[1].range.begin_loc()).line == 4);
  }
  r.in.run_buffer("bg2.geo", "Background Field = 4;\n");
  try {
    background_size_field(r.in);
    FAIL("expected a missing-field error");
  } catch (const RuntimeError& e) {
    CHECK(e.kind == lang::Diag::MissingBackgroundField);
    CHECK(e.message == "the background field, Field[4], is not defined");
    CHECK(r.sources.line_col(e.range.begin_loc()).line == 1);
  }
}

TEST_CASE("fields: diagnostic texts") {
  using testing::run_script;
  auto r = run_script("Field[1] = Treshold;\n");
  CHECK(r.rendered.find("unknown field type 'Treshold' (did you mean 'Threshold'?)") != std::string::npos);
  r = run_script("Field[1] = Threshold;\nField[1].LcMn = 1;\n");
  CHECK(r.rendered.find("Field[1] (Threshold) has no option 'LcMn' (did you mean 'LcMin'?)") !=
        std::string::npos);
  r = run_script("Field[1] = Threshold;\nField[1].InField = 5;\nx = FieldValue(1, 0, 0, 0);\n");
  CHECK(r.kinds == std::vector<std::string>{"3:5 missing-field"});
  CHECK(r.rendered.find("Field[1] (Threshold) references Field[5], which is not defined") != std::string::npos);
  CHECK(r.rendered.find("note: Field[1] refers to Field[5] here") != std::string::npos);
  r = run_script("Field[1] = Distance;\nField[1].CurvesList = 3;\n");
  CHECK(r.ok);
  CHECK(r.kinds == std::vector<std::string>{"2:23 field-list-without-braces"});
  CHECK(r.rendered.find("write {3}") != std::string::npos);
}
