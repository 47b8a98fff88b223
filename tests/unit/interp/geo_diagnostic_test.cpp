// Geometry kernel errors worded through the diagnostic table: the kernel's values, the
// table's sentence, the kind's kebab name the script tests match on.
#include <doctest/doctest.h>

#include <string>

#include "geo/model.h"
#include "interp/geo_diagnostic.h"
#include "lang/diagnostics.h"

using namespace sm;
using namespace sm::geo;
using sm::interp::geo_diagnostic;
using sm::lang::Diag;
using sm::lang::diag_info;

TEST_CASE("geo_diagnostic: a kernel error's values in its kind's sentence") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  const auto miss = m.add_curve(5, CurveKind::Line, {1, 9});
  REQUIRE_FALSE(miss);
  const auto d = geo_diagnostic(miss.error());
  CHECK(d.kind == Diag::GeoUnknownEntityUsedBy);
  CHECK(d.message == "unknown point 9 used by Line 5");
  CHECK(std::string(diag_info(d.kind).kebab) == "missing-entity");

  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  const auto twice = m.add_curve(1, CurveKind::Line, {2, 1});
  REQUIRE_FALSE(twice);
  CHECK(geo_diagnostic(twice.error()).message == "curve 1 already exists");
  CHECK(std::string(diag_info(geo_diagnostic(twice.error()).kind).kebab) == "duplicate-tag");
}

TEST_CASE("geo_diagnostic: loops, circles and holes, one kind per shape") {
  const GeoError reversed = make_error(GeoErrorId::LoopCurveReversed, EntityKind::CurveLoop, {7, 3, 2}, {4});
  CHECK(geo_diagnostic(reversed).message ==
        "curve loop 7 is broken at curve 2: it ends at point 4 where curve 3 also ends (use -3 to reverse it)");
  const GeoError open = make_error(GeoErrorId::LoopDoesNotClose, EntityKind::CurveLoop, {7, 2}, {4, 1});
  CHECK(geo_diagnostic(open).message ==
        "curve loop 7 does not close: curve 2 ends at point 4 but the loop started at point 1");
  CHECK(diag_info(geo_diagnostic(open).kind).kebab == diag_info(geo_diagnostic(reversed).kind).kebab);

  const GeoError radii = make_error(GeoErrorId::NotCocircular, EntityKind::Curve, {3}, {}, {1.0, 1.25});
  CHECK(geo_diagnostic(radii).message == "circle 3: control points are not cocircular (R1=1, R2=1.25)");
  const GeoError pole = make_error(GeoErrorId::HoleOutsidePolar, EntityKind::Surface, {1, 5, 2}, {9});
  CHECK(geo_diagnostic(pole).message.rfind(
            "plane surface 1: hole (curve loop 5) is not inside the outer curve loop 2: in the (u,v) plane of "
            "PolarSphere 9 every hole lies outside it",
            0) == 0);
  const GeoError centre =
      make_error(GeoErrorId::UnknownPartOf, EntityKind::Point, {8, 1}, {}, {}, {"centre", "PolarSphere"});
  CHECK(geo_diagnostic(centre).message == "unknown point 8 (centre of PolarSphere 1)");
  const GeoError gone = make_error(GeoErrorId::CannotActOnUnknown, EntityKind::Curve, {-4}, {}, {}, {"extrude"});
  CHECK(geo_diagnostic(gone).message == "cannot extrude unknown curve 4");
  CHECK(std::string(diag_info(geo_diagnostic(gone).kind).kebab) == "missing-entity");
}

TEST_CASE("geo_compat_diagnostic: the kernel's gmsh-compat notes carry values, the table words them") {
  Model m;
  REQUIRE(m.add_point(0, {0, 0, 0}));   // tag 0: accepted with a note
  REQUIRE(m.add_point(1, {1, 0, 0}));
  REQUIRE(m.add_curve(4, CurveKind::Line, {1, 1}));   // a line to itself: its tag taken, no curve
  REQUIRE(m.set_mesh_size({7}, 0.1));                  // a missing point: ignored with a note
  const auto notes = m.take_compat_notes();
  REQUIRE(notes.size() == 3);
  using sm::interp::geo_compat_diagnostic;
  CHECK(geo_compat_diagnostic(notes[0]).kind == Diag::GmshCompatTagZero);
  CHECK(geo_compat_diagnostic(notes[0]).message ==
        "point tag 0: Gmsh accepts it; so do we, but tags are meant to be positive");
  CHECK(geo_compat_diagnostic(notes[1]).message ==
        "line 4 goes from point 1 to itself: Gmsh keeps it as a degenerate curve with no mesh elements; we do not "
        "create it (only its tag is taken)");
  CHECK(geo_compat_diagnostic(notes[2]).message ==
        "MeshSize of point 7, which does not exist: Gmsh ignores it; so do we");
  for (const auto& n : notes) CHECK(std::string(diag_info(geo_compat_diagnostic(n).kind).kebab) == "gmsh-compat");

  Model::CompatNote later{Model::CompatNoteId::OuterListedLater, {3, 2, 1}, {}, std::nullopt};
  CHECK(geo_compat_diagnostic(later).message ==
        "plane surface 3: curve loop 2 encloses the others but is listed after curve loop 1; Gmsh finds the enclosing "
        "loop, and so do we: curve loop 2 is the outer one");
}
