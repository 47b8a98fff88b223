// Geometry statements through the interpreter: the model they build (the world_c script of
// tests/scripts/geometry), and kernel errors as located diagnostics with provenance notes.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "geo/model.h"
#include "interp/interpreter.h"
#include "interp_test_util.h"

using sm::interp::testing::run_script;

namespace {

const char* kSquare =
    "Point(1) = {0, 0, 0};\nPoint(2) = {1, 0, 0};\nPoint(3) = {1, 1, 0};\nPoint(4) = {0, 1, 0};\n"
    "Line(1) = {1, 2};\nLine(2) = {2, 3};\n";

}  // namespace

TEST_CASE("geometry: a broken curve loop names the curve and where it was created") {
  // Gmsh 4.8.4 creates such a loop unchecked (a warning); the surface it bounds is the error.
  const auto r =
      run_script(std::string(kSquare) +
                 "Line(3) = {4, 3};\nLine(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n");
  REQUIRE(r.kinds.size() == 2);
  CHECK(r.kinds[0] == "9:1 gmsh-compat");
  CHECK(r.kinds[1] == "10:1 loop-not-closed");
  CHECK(r.rendered.find("curve loop 1 is broken at curve 2") != std::string::npos);
  CHECK(r.rendered.find("test.geo:7:1: note: curve 3 was created here") != std::string::npos);
  CHECK(r.rendered.find("test.geo:6:1: note: curve 2 was created here") != std::string::npos);
}

TEST_CASE("geometry: entities made by Duplicata and Split Curve point at those statements") {
  auto r = run_script(std::string(kSquare) +
                      "c[] = Duplicata{ Curve{1}; };\nCurve Loop(1) = {c[0], 2};\nPlane Surface(1) = {1};\n");
  REQUIRE(r.kinds.size() == 2);
  CHECK(r.kinds[1] == "9:1 loop-not-closed");
  CHECK(r.rendered.find("test.geo:7:7: note: curve 3 was created here") != std::string::npos);
  r = run_script(
      "For i In {1:4}\n  Point(i) = {i, i * i, 0};\nEndFor\nSpline(1) = {1:4};\nSplit Curve{1} Point{2};\n"
      "Line(2) = {1, 4};\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "6:1 duplicate-tag");
  CHECK(r.rendered.find("test.geo:5:1: note: curve 2 was created here") != std::string::npos);   // a piece of curve 1
}

TEST_CASE("geometry: a duplicate point inside a loop shows both the first definition and the loop") {
  const auto r = run_script("Point(2) = {0, 0, 0};\nFor i In {1:3}\n  Point(i) = {i, 0, 0};\nEndFor\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "3:3 duplicate-tag");
  CHECK(r.rendered.find("test.geo:1:1: note: point 2 was created here") != std::string::npos);
  CHECK(r.rendered.find("i = 2") != std::string::npos);
}

TEST_CASE("geometry: the world_c script is one valid face on the PolarSphere, Antarctica outer") {
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  std::ostringstream out;
  sm::interp::Interpreter in(sources, diags, out);
  REQUIRE(in.run_file(std::string(SM_TEST_DATA) + "/geo_scripts/world_c.geo") == sm::interp::RunStatus::Ok);
  CHECK(diags.error_count() == 0);
  const sm::geo::Model& m = in.kernel().model;
  REQUIRE(m.surfaces().size() == 1);
  const sm::geo::ModelSurface& s = *m.surface(1);
  CHECK(s.geometry == 1);
  REQUIRE(s.loops.size() == 743);   // 1 outer + 742 holes
  CHECK(s.loops[0] == 5);           // Antarctica (segment 5 of world_c.txt)
  int points = 0;
  for (int l : s.loops) {
    const sm::geo::ModelCurveLoop* loop = m.curve_loop(std::abs(l));
    REQUIRE(loop);
    REQUIRE(loop->curves.size() == 1);
    const sm::geo::ModelCurve* c = m.curve(std::abs(loop->curves[0]));
    REQUIRE(c);
    CHECK(c->kind == sm::geo::CurveKind::BSpline);
    CHECK(c->periodic());
    CHECK(c->geometry == 1);
    REQUIRE(c->shape);
    // The closed curve returns to its first point on the unit sphere.
    CHECK(sm::norm(c->shape->point(0.0) - c->shape->point(1.0)) < 1e-12);
    CHECK(std::abs(sm::norm(c->shape->point(0.37)) - 1.0) < 1e-12);
    points += static_cast<int>(c->points.size()) - 1;
    CHECK(in.kernel().created_at.count({1, c->tag}) == 1);
  }
  CHECK(points == 7156);   // 7,899 vertices less the 743 closing copies
}

// The transforms' argument messages show Gmsh's syntax once: the message is the format's
// only argument, printed as it is, so its braces are not doubled.
TEST_CASE("Rotate and Dilate with the wrong arguments name their syntax with single braces") {
  const auto rot = run_script("Point(1) = {1, 0, 0};\nRotate{{0, 0, 1}, Pi / 2}{ Point{1}; }\n");
  CHECK_FALSE(rot.ok);
  CHECK(rot.rendered.find("Rotate needs {{ax, ay, az}, {px, py, pz}, angle}") != std::string::npos);
  CHECK(rot.rendered.find("{{{{") == std::string::npos);
  const auto dil = run_script("Point(1) = {1, 0, 0};\nDilate{{0, 0, 0}}{ Point{1}; }\n");
  CHECK_FALSE(dil.ok);
  CHECK(dil.rendered.find("Dilate needs {{cx, cy, cz}, factor}") != std::string::npos);
}
