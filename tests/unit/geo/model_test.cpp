// The model: Gmsh 4.8.4's tag rules, located validation errors, loops, plane surfaces on a
// PolarSphere, physical groups, Boundary queries, Delete, Coherence, transforms, Split Curve.
// Expected values marked "Gmsh" were printed by gmsh 4.8.4 on the same statements: the
// scripts and their output are in tests/data/geo/gmsh_queries (run.sh regenerates them).
#include "geo/model.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace sm;
using namespace sm::geo;

namespace {

std::vector<int> tags_of(const std::vector<DimTag>& v) {
  std::vector<int> out;
  for (DimTag d : v) out.push_back(d.tag);
  return out;
}

// Two unit squares side by side sharing curve 2 (the p.geo script of the comments).
Model two_squares() {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_point(3, {1, 1, 0}));
  REQUIRE(m.add_point(4, {0, 1, 0}));
  REQUIRE(m.add_point(5, {2, 0, 0}));
  REQUIRE(m.add_point(6, {2, 1, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Line, {3, 4}));
  REQUIRE(m.add_curve(4, CurveKind::Line, {4, 1}));
  REQUIRE(m.add_curve(5, CurveKind::Line, {2, 5}));
  REQUIRE(m.add_curve(6, CurveKind::Line, {5, 6}));
  REQUIRE(m.add_curve(7, CurveKind::Line, {6, 3}));
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}));
  REQUIRE(m.add_plane_surface(1, {1}));
  REQUIRE(m.add_curve_loop(2, {5, 6, 7, -2}));
  REQUIRE(m.add_plane_surface(2, {2}));
  return m;
}

}  // namespace

TEST_CASE("model tags: newp/newl/newll/news/newreg with Geometry.OldNewReg = 1 and 0") {
  Model m;
  for (int i = 1; i <= 3; ++i) REQUIRE(m.add_point(i, {double(i), 0, 0}));
  REQUIRE(m.add_point(20, {0, 1, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Line, {3, 20}));
  // Gmsh: A newp=21 newl=4 newreg=4 newll=4 news=4
  CHECK(m.new_point_tag() == 21);
  CHECK(m.new_curve_tag() == 4);
  CHECK(m.new_reg() == 4);
  CHECK(m.new_loop_tag() == 4);
  CHECK(m.new_surface_tag() == 4);
  // Deleting a used point is skipped; deleting the max tag lowers the mark by one.
  std::vector<DimTag> skipped;
  REQUIRE(m.remove({{0, 20}}, false, &skipped));
  CHECK(skipped.size() == 1);
  CHECK(m.new_point_tag() == 21);
  REQUIRE(m.remove({{1, 3}}, false));
  REQUIRE(m.remove({{0, 20}}, false));
  CHECK(m.new_point_tag() == 20);   // Gmsh: C newp=20 newl=3 newreg=3
  CHECK(m.new_curve_tag() == 3);
  auto p = m.add_physical(0, 40, "", {1});
  REQUIRE(p);
  CHECK(m.new_reg() == 41);         // Gmsh: D newreg=41 newp=20
  auto named = m.add_physical(1, std::nullopt, "a", {1});
  REQUIRE(named);
  CHECK(*named == 41);
  CHECK(m.new_reg() == 42);         // Gmsh: E newreg=42
  m.options().old_new_reg = false;
  CHECK(m.new_curve_tag() == 3);    // Gmsh: F newp=20 newl=3 newreg=42 newll=1 news=1
  CHECK(m.new_loop_tag() == 1);
  CHECK(m.new_surface_tag() == 1);
  CHECK(m.new_reg() == 42);
  REQUIRE(m.add_curve_loop(70, {1, -1}));   // closes (there and back), as Gmsh accepts
  CHECK(m.new_curve_tag() == 3);            // Gmsh: G newl=3 newreg=71 newll=71
  CHECK(m.new_reg() == 71);
  CHECK(m.new_loop_tag() == 71);
  m.set_max_tag(0, 100);
  CHECK(m.new_point_tag() == 101);  // Gmsh: SetMaxTag Point(100) -> newp=101
}

TEST_CASE("model tags: the reference's verified example (curves 1-3, loop 7, surface 4, physical 11)") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_point(20, {0, 1, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 20}));
  REQUIRE(m.add_curve(3, CurveKind::Line, {20, 1}));
  REQUIRE(m.add_curve_loop(7, {1, 2, 3}));
  REQUIRE(m.add_plane_surface(4, {7}));
  REQUIRE(m.add_physical(2, 11, "", {4}));
  CHECK(m.new_curve_tag() == 12);
  CHECK(m.new_surface_tag() == 12);
  CHECK(m.new_loop_tag() == 12);
  CHECK(m.new_point_tag() == 21);
}

TEST_CASE("model errors: missing point, duplicate tag, self reference, bad tag") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  auto dup = m.add_point(1, {1, 0, 0});
  REQUIRE_FALSE(dup);
  CHECK(dup.error().kind == GeoErrorKind::DuplicateTag);
  CHECK(dup.error().entity == EntityKind::Point);
  CHECK(dup.error().tags == std::vector<int>{1});
  auto miss = m.add_curve(5, CurveKind::Line, {1, 9});
  REQUIRE_FALSE(miss);
  CHECK(miss.error().kind == GeoErrorKind::MissingEntity);
  CHECK(miss.error().tags == std::vector<int>{9, 5});
  CHECK(miss.error().id == GeoErrorId::UnknownEntityUsedBy);
  CHECK(miss.error().words == std::vector<std::string>{"Line"});
  auto self = m.add_curve(6, CurveKind::Spline, {1, 1});
  REQUIRE_FALSE(self);
  CHECK(self.error().kind == GeoErrorKind::SelfReference);
  CHECK(self.error().tags == std::vector<int>{6, 1});
  // A Line from a point to itself: Gmsh keeps a degenerate curve; we take its tag only, with a note.
  CHECK(m.take_compat_notes().empty());
  REQUIRE(m.add_curve(6, CurveKind::Line, {1, 1}));
  CHECK_FALSE(m.curve(6));
  CHECK(m.new_curve_tag() == 7);
  CHECK(m.take_compat_notes().size() == 1);
  CHECK(m.add_point(-1, {0, 0, 0}).error().kind == GeoErrorKind::InvalidTag);
  // Tag 0: Gmsh takes it for a point (with a note here), not for a curve.
  REQUIRE(m.add_point(0, {0, 0, 5}));
  CHECK(m.vertex(0)->xyz == Vec3{0, 0, 5});
  CHECK(m.take_compat_notes().size() == 1);
  CHECK(m.add_curve(0, CurveKind::Line, {0, 1}).error().kind == GeoErrorKind::InvalidTag);
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  CHECK(m.add_curve(1, CurveKind::Line, {2, 1}).error().kind == GeoErrorKind::DuplicateTag);
  CHECK(m.add_curve(2, CurveKind::Circle, {1, 2, 1}).error().kind == GeoErrorKind::SelfReference);
  CHECK(m.curves().size() == 1);   // failed statements leave nothing behind
  // B-splines may repeat control points (Gmsh sharpens the curve there); lines may not.
  REQUIRE(m.add_point(3, {1, 1, 0}));
  CHECK(m.add_curve(3, CurveKind::BSpline, {1, 2, 2, 3}));
  CHECK(m.add_curve(4, CurveKind::Line, {1, 2, 2, 3}).error().kind == GeoErrorKind::SelfReference);
  CHECK(m.add_curve(5, CurveKind::BSpline, {1, 1}).error().kind == GeoErrorKind::SelfReference);
  const double nan = std::nan("");
  CHECK(m.add_point(9, {nan, 0, 0}).error().kind == GeoErrorKind::BadArgument);
  CHECK(m.add_point(9, {0, 0, 0}, HUGE_VAL).error().kind == GeoErrorKind::BadArgument);
  CHECK_FALSE(m.vertex(9));
}

TEST_CASE("curve loops: closing, Gmsh's reordering, subloops, located breaks") {
  Model m = two_squares();
  REQUIRE(m.add_curve_loop(10, {1, 3, 2, 4}));   // Gmsh reorders: 1 2 3 4
  CHECK(m.curve_loop(10)->curves == std::vector<int>{1, 2, 3, 4});
  CHECK(m.curve_loop(10)->reordered);
  REQUIRE(m.add_curve_loop(11, {-1, -4, -3, -2}));
  CHECK_FALSE(m.curve_loop(11)->reordered);
  // Gmsh 4.8.4 creates a loop that does not close unchecked (Geo/Geo.cpp's SortEdgesInLoop):
  // kept as written with why, here with the curve that breaks it; a surface on it is the error.
  REQUIRE(m.add_curve_loop(12, {1, 2, -3, 4}));
  const std::optional<GeoError>& wrong = m.curve_loop(12)->unclosed;
  REQUIRE(wrong);
  CHECK(wrong->kind == GeoErrorKind::LoopNotClosed);
  CHECK(wrong->tags == std::vector<int>{12, -3, 2});
  CHECK(wrong->id == GeoErrorId::LoopCurveReversed);   // "... (use 3 to reverse it)"
  CHECK(m.curve_loop(12)->curves == std::vector<int>{1, 2, -3, 4});
  CHECK(m.add_plane_surface(90, {12}).error().kind == GeoErrorKind::LoopNotClosed);
  CHECK(m.add_surface_filling(91, {12}, std::nullopt).error().kind == GeoErrorKind::LoopNotClosed);
  CHECK_FALSE(m.surface(90));
  REQUIRE(m.add_curve_loop(13, {1, 2, 3}));
  const std::optional<GeoError>& open = m.curve_loop(13)->unclosed;
  REQUIRE(open);
  CHECK(open->tags == std::vector<int>{13, 3});
  CHECK(open->id == GeoErrorId::LoopDoesNotClose);
  CHECK(open->ids == std::vector<int>{4, 1});   // curve 3 ends at point 4, the loop started at point 1
  REQUIRE(m.add_curve_loop(14, {1, 2, 3, 4, 5}));
  REQUIRE(m.curve_loop(14)->unclosed);
  CHECK(m.curve_loop(14)->unclosed->tags == std::vector<int>{14, 5});
  CHECK_FALSE(m.curve_loop(10)->unclosed);
  CHECK(m.add_curve_loop(15, {1, 2, 99}).error().kind == GeoErrorKind::MissingEntity);
  CHECK(m.add_curve_loop(16, {}).error().kind == GeoErrorKind::LoopEmpty);
  // Two closed chains in one loop: Gmsh's "subloop", accepted.
  REQUIRE(m.add_curve_loop(17, {1, 2, 3, 4, 5, 6, 7, -2}));
  CHECK(m.curve_loop(17)->curves.size() == 8);
  CHECK(m.add_curve_loop(17, {1, 2, 3, 4}).error().kind == GeoErrorKind::DuplicateTag);
}

TEST_CASE("plane surfaces: holes inside, holes outside, shared curves") {
  Model m;
  const double sq[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_point(i + 1, {sq[i][0], sq[i][1], 0}));
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, CurveKind::Line, {i + 1, (i + 1) % 4 + 1}));
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}));
  // A circle hole inside, drawn with two arcs, and one outside.
  auto add_circle = [&](int base, double cx, double cy) {
    REQUIRE(m.add_point(base, {cx, cy, 0}));
    REQUIRE(m.add_point(base + 1, {cx + 1, cy, 0}));
    REQUIRE(m.add_point(base + 2, {cx - 1, cy, 0}));
    REQUIRE(m.add_curve(base, CurveKind::Circle, {base + 1, base, base + 2}, Vec3{0, 0, 1}));
    REQUIRE(m.add_curve(base + 1, CurveKind::Circle, {base + 2, base, base + 1}, Vec3{0, 0, 1}));
    REQUIRE(m.add_curve_loop(base, {base, base + 1}));
  };
  add_circle(10, 5, 5);
  add_circle(20, 15, 5);
  add_circle(30, 9.5, 5);   // crosses the outer boundary
  REQUIRE(m.add_plane_surface(1, {1, 10}));
  CHECK(m.surface(1)->geometry == 0);
  auto out = m.add_plane_surface(2, {1, 20});
  REQUIRE_FALSE(out);
  CHECK(out.error().kind == GeoErrorKind::HoleOutside);
  CHECK(out.error().tags == std::vector<int>{2, 20, 1});
  // A hole that crosses the outer loop: Gmsh meshes the discretised curves, so the model
  // keeps it with a compat note and leaves the crossing to the 1D mesher's check.
  m.take_compat_notes();
  REQUIRE(m.add_plane_surface(3, {1, 30}));
  CHECK(m.take_compat_notes().size() == 1);
  auto shared = m.add_plane_surface(4, {1, 1});
  REQUIRE_FALSE(shared);
  CHECK(shared.error().kind == GeoErrorKind::SharedBoundary);
  CHECK(m.add_plane_surface(5, {1, 77}).error().kind == GeoErrorKind::MissingEntity);
  // A tilted plane works in its own mean plane.
  Model t;
  for (int i = 0; i < 4; ++i) REQUIRE(t.add_point(i + 1, {sq[i][0], sq[i][1], 0.5 * sq[i][0]}));
  for (int i = 0; i < 4; ++i) REQUIRE(t.add_curve(i + 1, CurveKind::Line, {i + 1, (i + 1) % 4 + 1}));
  REQUIRE(t.add_curve_loop(1, {1, 2, 3, 4}));
  const double hole[4][2] = {{4, 4}, {6, 4}, {6, 6}, {4, 6}};
  for (int i = 0; i < 4; ++i) REQUIRE(t.add_point(i + 11, {hole[i][0], hole[i][1], 0.5 * hole[i][0]}));
  for (int i = 0; i < 4; ++i) REQUIRE(t.add_curve(i + 11, CurveKind::Line, {i + 11, (i + 1) % 4 + 11}));
  REQUIRE(t.add_curve_loop(2, {11, 12, 13, 14}));
  CHECK(t.add_plane_surface(1, {1, 2}));
}

TEST_CASE("PolarSphere geometry: points in (u,v), curves and surfaces on it") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {0, 0, 1}));
  CHECK(m.add_polar_sphere(1, 1, 99).error().kind == GeoErrorKind::MissingEntity);
  CHECK(m.add_polar_sphere(1, 1, 1).error().kind == GeoErrorKind::CoincidentPoints);
  REQUIRE(m.add_polar_sphere(1, 1, 2));
  CHECK(m.current_geometry() == 1);
  REQUIRE(m.add_point(3, {-0.3, -0.3, 123.0}));   // z ignored
  const ModelVertex* v = m.vertex(3);
  CHECK(v->geometry == 1);
  CHECK(std::abs(v->xyz.x - 0.50847) < 1e-5);
  CHECK(std::abs(v->xyz.z - 0.69492) < 1e-5);
  CHECK(v->lc == kMaxLc);
  REQUIRE(m.add_point(4, {0.3, -0.3, 0}, 0.1));
  REQUIRE(m.add_point(5, {0.3, 0.3, 0}));
  REQUIRE(m.add_point(6, {-0.3, 0.3, 0}));
  REQUIRE(m.add_curve(1, CurveKind::BSpline, {3, 4, 5, 6, 3}));
  CHECK(m.curve(1)->geometry == 1);
  CHECK(m.curve(1)->periodic());
  CHECK(m.curve(1)->shape->defined_in_uv());
  REQUIRE(m.add_curve_loop(1, {1}));
  REQUIRE(m.add_plane_surface(1, {1}));
  CHECK(m.surface(1)->geometry == 1);
  // A curve mixing Euclidean and sphere points drops the geometry (Gmsh).
  REQUIRE(m.add_curve(2, CurveKind::Line, {1, 3}));
  CHECK(m.curve(2)->geometry == 0);
  m.set_euclidean();
  REQUIRE(m.add_point(7, {0.5, 0.5, 0.5}));
  CHECK(m.vertex(7)->geometry == 0);
  REQUIRE(m.set_current_geometry(1));
  CHECK(m.set_current_geometry(8).error().kind == GeoErrorKind::MissingEntity);
  REQUIRE(m.add_lonlat_sphere(2, 1, 2));
  REQUIRE(m.add_point(8, {0.5, 0.25, 0}));
  CHECK(norm(m.vertex(8)->xyz - Vec3{std::cos(0.25) * std::cos(0.5), std::cos(0.25) * std::sin(0.5), std::sin(0.25)}) <
        1e-15);
  REQUIRE(m.set_mesh_size({3, 4}, 0.5));
  CHECK(m.vertex(4)->lc == 0.5);
  // An unknown point: Gmsh ignores it; the known ones still get the size.
  m.take_compat_notes();
  REQUIRE(m.set_mesh_size({42, 3}, 0.25));
  CHECK(m.vertex(3)->lc == 0.25);
  CHECK(m.take_compat_notes().size() == 1);
}

TEST_CASE("physical groups: Gmsh's auto tags, names, += and -=") {
  Model m = two_squares();
  REQUIRE(m.add_physical(1, 5, "", {1}));
  auto again = m.add_physical(1, 5, "", {2});   // Gmsh: "Physical curve 5 already exists"
  REQUIRE_FALSE(again);
  CHECK(again.error().kind == GeoErrorKind::DuplicateTag);
  REQUIRE(m.add_physical(1, 5, "", {3}, PhysicalOp::Add));
  CHECK(m.physical(1, 5)->entities == std::vector<int>{1, 3});
  REQUIRE(m.add_physical(1, 5, "", {1}, PhysicalOp::Remove));
  CHECK(m.physical(1, 5)->entities == std::vector<int>{3});
  CHECK(*m.add_physical(1, std::nullopt, "coast", {4}) == 6);
  CHECK(*m.add_physical(2, std::nullopt, "sea", {1, 2}) == 7);
  CHECK(*m.add_physical(1, std::nullopt, "coast", {5}, PhysicalOp::Add) == 6);
  CHECK(*m.add_physical(1, 20, "open", {6}) == 20);
  CHECK(*m.add_physical(0, std::nullopt, "p", {1}) == 21);
  CHECK(m.new_reg() == 22);   // Gmsh: newreg 22
  CHECK(m.add_physical(1, std::nullopt, "x", {99}).error().kind == GeoErrorKind::MissingEntity);
  // Signs are kept for MSH 2 orientation; the script query lists tags unsigned (gmsh 4.8.4
  // prints "2 3 4" for Physical Curve{6} after += {-4}).
  REQUIRE(m.add_physical(1, 6, "", {-7}, PhysicalOp::Add));
  CHECK(m.physical(1, 6)->entities == std::vector<int>{4, 5, -7});
  CHECK(m.physical_entities(1, 6) == std::vector<int>{4, 5, 7});
  CHECK(m.physical_entities(1, 99).empty());
}

TEST_CASE("Boundary and CombinedBoundary as Gmsh prints them") {
  const Model m = two_squares();
  auto b = [&](std::vector<DimTag> e, bool combined) { return tags_of(*m.boundary(e, combined)); };
  CHECK(b({{2, 1}}, false) == std::vector<int>{1, 2, 3, 4});                  // Gmsh bs1
  CHECK(b({{2, 2}}, false) == std::vector<int>{5, 6, 7, -2});                 // Gmsh bs2
  CHECK(b({{2, 1}, {2, 2}}, true) == std::vector<int>{1, 3, 4, 5, 6, 7});     // Gmsh cb
  CHECK(b({{2, 1}, {2, 2}}, false) == std::vector<int>{1, 2, 3, 4, 5, 6, 7, -2});
  CHECK(b({{1, 1}, {1, 5}}, true) == std::vector<int>{1, 5});                 // Gmsh cbc
  CHECK(b({{1, 1}, {1, 5}}, false) == std::vector<int>{1, 2, 2, 5});          // Gmsh bc
  CHECK(b({{1, -1}}, false) == std::vector<int>{2, 1});                       // Gmsh Bn
  CHECK(m.boundary({{1, 42}}, false).error().kind == GeoErrorKind::MissingEntity);
  CHECK(m.tags(1) == std::vector<int>{1, 2, 3, 4, 5, 6, 7});
  const BoundingBox bb = m.bounding_box();
  CHECK(bb.hi.x == 2.0);
  CHECK(bb.diagonal() == doctest::Approx(std::sqrt(5.0)));
}

TEST_CASE("Delete: skipped when used, Recursive removes unused sub-entities") {
  Model m = two_squares();
  const auto group = m.add_physical(1, std::nullopt, "open", {6});
  REQUIRE(group);
  std::vector<DimTag> skipped;
  REQUIRE(m.remove({{1, 2}}, false, &skipped));   // used by both loops
  CHECK(skipped.size() == 1);
  CHECK(m.curve(2));
  REQUIRE(m.remove({{2, 2}}, true));
  CHECK(m.tags(2) == std::vector<int>{1});
  CHECK(m.tags(1) == std::vector<int>{1, 2, 3, 4});   // Gmsh leaves 1..4, as here
  CHECK(m.tags(0) == std::vector<int>{1, 2, 3, 4});   // Gmsh 4.8.4 leaves points 5, 6 orphaned: we do not
  // The group keeps the tag (Gmsh's: a curve 6 made again is in it) but lists no curve.
  CHECK(m.physicals().size() == 1);
  CHECK(m.physical_entities(1, *group).empty());
  CHECK(m.loop_tags() == std::vector<int>{1});
  CHECK(m.remove({{0, 77}}, false).error().kind == GeoErrorKind::MissingEntity);
}

TEST_CASE("Coherence merges duplicate points (lowest tag) and duplicate curves") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_point(3, {1 + 1e-12, 1e-12, 0}));
  REQUIRE(m.add_point(4, {0, 1, 0}));
  REQUIRE(m.add_point(5, {1, 1e-3, 0}));   // far beyond 1e-8 x diagonal
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {1, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Line, {3, 4}));
  REQUIRE(m.add_curve(4, CurveKind::Line, {4, 1}));
  REQUIRE(m.add_curve_loop(1, {2, 3, 4}));
  REQUIRE(m.add_physical(0, 1, "", {3}));
  CHECK(m.coherence() == 2);   // point 3 into 2, then curve 2 into 1
  CHECK(m.tags(0) == std::vector<int>{1, 2, 4, 5});
  CHECK(m.tags(1) == std::vector<int>{1, 3, 4});
  CHECK(m.curve(3)->points == std::vector<int>{2, 4});
  CHECK(m.curve_loop(1)->curves == std::vector<int>{1, 3, 4});
  CHECK(m.physical(0, 1)->entities == std::vector<int>{2});
  CHECK(m.coherence() == 0);
}

TEST_CASE("Duplicata and transforms, with AutoCoherence (Gmsh's d.geo)") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_point(3, {1, 1, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
  auto dup = m.duplicate({{0, 1}, {1, 2}});
  REQUIRE(dup);
  CHECK(tags_of(*dup) == std::vector<int>{4, 3});   // Gmsh: T [0]4 [1]3
  REQUIRE(m.translate(*dup, {1, 0, 0}));
  CHECK(m.tags(0) == std::vector<int>{1, 2, 3, 5, 6});   // Gmsh: pts 1 2 3 5 6
  CHECK(tags_of(*m.boundary({{1, 3}}, false)) == std::vector<int>{5, 6});   // Gmsh: bnd3 5 6
  CHECK(norm(m.vertex(6)->xyz - Vec3{2, 1, 0}) == 0);
  REQUIRE(m.rotate({{0, 3}}, {0, 0, 1}, {0, 0, 0}, kPi / 2));
  CHECK(norm(m.vertex(3)->xyz - Vec3{-1, 1, 0}) < 1e-15);   // Gmsh: p3 -1 1 0
  CHECK(norm(m.curve(2)->shape->end_point() - Vec3{-1, 1, 0}) < 1e-15);
  auto sym = m.duplicate({{1, 1}});
  REQUIRE(sym);
  REQUIRE(m.symmetry(*sym, 1, 0, 0, 0));
  const ModelCurve* c = m.curve(sym->front().tag);
  REQUIRE(c);
  CHECK(c->points.front() == 1);   // the mirrored copy of point 1 merged back into it
  CHECK(norm(m.vertex(c->points.back())->xyz - Vec3{-1, 0, 0}) == 0);
  REQUIRE(m.dilate({{0, 5}}, {0, 0, 0}, {2, 3, 4}));
  CHECK(norm(m.vertex(5)->xyz - Vec3{4, 0, 0}) == 0);
  CHECK(m.translate({{1, 99}}, {1, 0, 0}).error().kind == GeoErrorKind::MissingEntity);
  CHECK(m.rotate({{0, 1}}, {0, 0, 0}, {0, 0, 0}, 1.0).error().kind == GeoErrorKind::BadArgument);
}

TEST_CASE("transforms keep PolarSphere points on the sphere; surfaces duplicate with loops") {
  Model m;
  REQUIRE(m.add_point(100, {0, 0, 0}));
  REQUIRE(m.add_point(101, {0, 0, 2}));
  REQUIRE(m.add_polar_sphere(1, 100, 101));
  REQUIRE(m.add_point(1, {0.1, 0.2, 0}));
  REQUIRE(m.add_point(2, {0.3, 0.2, 0}));
  REQUIRE(m.add_point(3, {0.2, 0.4, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Line, {3, 1}));
  REQUIRE(m.add_curve_loop(1, {1, 2, 3}));
  REQUIRE(m.add_plane_surface(1, {1}));
  auto copy = m.duplicate({{2, 1}});
  REQUIRE(copy);
  const int s = copy->front().tag;
  // Rotation about the polar axis: (u,v) rotates by the same angle.
  REQUIRE(m.rotate(*copy, {0, 0, 1}, {0, 0, 0}, kPi / 2));
  const ModelSurface* ns = m.surface(s);
  REQUIRE(ns);
  CHECK(ns->geometry == 1);
  const int c0 = std::abs(m.curve_loop(std::abs(ns->loops[0]))->curves[0]);
  const ModelVertex* v = m.vertex(m.curve(c0)->begin);
  CHECK(v->geometry == 1);
  CHECK(std::abs(norm(v->xyz) - 2) < 1e-14);
  CHECK(norm(v->uv - Vec2{-0.2, 0.1}) < 1e-14);
  CHECK(m.surfaces().size() == 2);
}

TEST_CASE("Split Curve: Gmsh's pieces and tags (sp.geo)") {
  Model m;
  for (int i = 1; i <= 6; ++i) REQUIRE(m.add_point(i, {std::cos(double(i)), std::sin(double(i)), 0}));
  REQUIRE(m.add_curve(1, CurveKind::BSpline, {1, 2, 3, 4, 5, 6, 1}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {1, 2, 3, 4, 5, 6}));
  REQUIRE(m.add_curve_loop(1, {-1}));
  auto a = m.split_curve(1, {3, 5});
  REQUIRE(a);
  CHECK(*a == std::vector<int>{3, 4});
  CHECK(m.curve(3)->points == std::vector<int>{3, 4, 5});          // Gmsh: BSpline(3) = {3, 4, 5}
  CHECK(m.curve(4)->points == std::vector<int>{5, 6, 1, 2, 3});    // Gmsh: BSpline(4) = {5, 6, 1, 2, 3}
  CHECK(m.curve_loop(1)->curves == std::vector<int>{-4, -3});
  CHECK_FALSE(m.curve(1));
  auto b = m.split_curve(2, {2, 4});
  REQUIRE(b);
  CHECK(*b == std::vector<int>{5, 6, 7});
  CHECK(m.curve(6)->points == std::vector<int>{2, 3, 4});          // Gmsh: Line(6) = {2, 3, 4}
  CHECK(m.new_curve_tag() == 8);                                   // Gmsh: newl 8
  // Point 6 is not a control point of curve 5: skipped (with a note), as Gmsh does; the
  // curve is replaced by one piece with a new tag, as Gmsh's Split Curve does.
  m.take_compat_notes();
  auto none = m.split_curve(5, {6});
  REQUIRE(none);
  CHECK(*none == std::vector<int>{8});
  CHECK_FALSE(m.curve(5));
  CHECK(m.take_compat_notes().size() == 1);
  CHECK(m.split_curve(1, {2}).error().kind == GeoErrorKind::MissingEntity);
}

TEST_CASE("In BoundingBox queries (Gmsh's bb.geo)") {
  Model m;
  const Vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 1.3, 0}};
  for (int i = 0; i < 5; ++i) REQUIRE(m.add_point(i + 1, p[i]));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Circle, {3, 4, 1}));
  REQUIRE(m.add_curve(4, CurveKind::Line, {4, 1}));
  const Vec3 lo{-0.1, -0.1, -0.1};
  CHECK(m.in_bounding_box(0, lo, {1.1, 1.1, 0.1}) == std::vector<int>{1, 2, 3, 4});    // Gmsh: pts 1 2 3 4
  CHECK(m.in_bounding_box(1, lo, {1.1, 1.05, 0.1}) == std::vector<int>{1, 2, 3, 4});   // Gmsh: curves2
  REQUIRE(m.add_curve(5, CurveKind::Spline, {1, 5, 3}));
  CHECK(m.in_bounding_box(1, lo, {1.1, 1.1, 0.1}) == std::vector<int>{1, 2, 3, 4});    // Gmsh: curves3
  CHECK(m.in_bounding_box(1, lo, {1.1, 1.35, 0.1}) == std::vector<int>{1, 2, 3, 4, 5}); // Gmsh: curves4
  REQUIRE(m.add_curve_loop(1, {1, 2, 3}));
  REQUIRE(m.add_plane_surface(1, {1}));
  CHECK(m.in_bounding_box(2, lo, {1.1, 1.1, 0.1}) == std::vector<int>{1});
  CHECK(m.in_bounding_box(2, lo, {0.9, 1.1, 0.1}).empty());
  CHECK(m.curve_bounding_box(99).empty());
}

TEST_CASE("Coherence tolerance is Geometry.Tolerance x bounding-box diagonal (Gmsh's co.geo)") {
  // Gmsh 4.8.4: points (0,0,0), (2,0,0), (0,d,0); Coherence merges point 3 for d = 5e-9 and
  // 2e-8 (eps = 1e-8 x 2) and keeps it for d = 5e-8.
  for (auto [d, merged] : {std::pair{5e-9, true}, std::pair{2e-8, true}, std::pair{5e-8, false}}) {
    Model m;
    REQUIRE(m.add_point(1, {0, 0, 0}));
    REQUIRE(m.add_point(2, {2, 0, 0}));
    REQUIRE(m.add_point(3, {0, d, 0}));
    m.coherence();
    CHECK((m.vertex(3) == nullptr) == merged);
  }
  Model m;
  m.options().tolerance = 1e-3;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {2, 0, 0}));
  REQUIRE(m.add_point(3, {0, 1e-3, 0}));
  CHECK(m.coherence() == 1);
}

TEST_CASE("next tags after Coherence follow Geometry.OldNewReg (gmsh_queries/duplicata_oldnewreg.geo)") {
  for (bool old_new_reg : {true, false}) {
    Model m;
    m.options().old_new_reg = old_new_reg;
    REQUIRE(m.add_point(1, {0, 0, 0}));
    REQUIRE(m.add_point(2, {1, 0, 0}));
    REQUIRE(m.add_point(3, {1, 1, 0}));
    REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
    REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
    REQUIRE(m.add_point(7, {5, 5, 5}));
    REQUIRE(m.add_point(8, {5, 5, 5}));   // merged into 7 by the transform's coherence
    REQUIRE(m.translate({{0, 1}}, {0, 0, 0}));
    // Gmsh: the mark follows the survivors with OldNewReg = 1 and stays with 0.
    CHECK(m.new_point_tag() == (old_new_reg ? 8 : 9));
  }
}

TEST_CASE("a transform that breaks an arc fails and leaves the model unchanged") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_point(3, {0, 1, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Circle, {2, 1, 3}));
  // Stretching y by 2 makes the end radius 2 against a start radius 1: not cocircular.
  auto st = m.dilate({{1, 1}}, {0, 0, 0}, {1, 2, 1});
  REQUIRE_FALSE(st);
  CHECK(st.error().kind == GeoErrorKind::NotCocircular);
  CHECK(st.error().tags == std::vector<int>{1});
  CHECK(norm(m.vertex(3)->xyz - Vec3{0, 1, 0}) == 0);
  CHECK(norm(m.curve(1)->shape->point(0.5) - Vec3{std::sqrt(0.5), std::sqrt(0.5), 0}) < 1e-15);
  REQUIRE(m.dilate({{1, 1}}, {0, 0, 0}, {2, 2, 2}));   // uniform: fine
  CHECK(norm(m.curve(1)->shape->point(0.5) - Vec3{std::sqrt(2.0), std::sqrt(2.0), 0}) < 1e-14);
}

TEST_CASE("Split Curve inside a loop and a physical group (gmsh_queries/split_in_loop.geo)") {
  Model m;
  const Vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_point(i + 1, p[i]));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2, 3}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {3, 4, 1}));
  REQUIRE(m.add_curve_loop(1, {1, 2}));
  REQUIRE(m.add_plane_surface(1, {1}));
  REQUIRE(m.add_physical(1, 7, "", {1}));
  auto pieces = m.split_curve(1, {2});
  REQUIRE(pieces);
  CHECK(*pieces == std::vector<int>{8, 9});                                    // newreg after physical 7
  CHECK(m.tags(1) == std::vector<int>{2, 8, 9});                               // Gmsh: curves 2 8 9
  CHECK(tags_of(*m.boundary({{2, 1}}, false)) == std::vector<int>{8, 9, 2});   // Gmsh: bnd 8 9 2
  CHECK(m.physical_entities(1, 7) == std::vector<int>{8, 9});                  // Gmsh: phys 8 9
}

TEST_CASE("model: every change gives a new revision, queries and copies keep it") {
  Model m;
  CHECK(m.revision() == 0);
  std::vector<std::uint64_t> seen{m.revision()};
  auto changed = [&] {
    const std::uint64_t r = m.revision();
    const bool fresh = std::find(seen.begin(), seen.end(), r) == seen.end();
    seen.push_back(r);
    return fresh;
  };
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  CHECK(changed());
  REQUIRE(m.add_point(2, {1, 0, 0}).ok());
  CHECK(changed());
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}).ok());
  CHECK(changed());
  const Model copy = m;
  CHECK(copy.revision() == m.revision());
  (void)m.bounding_box();
  (void)m.tags(0);
  CHECK(m.revision() == copy.revision());
  REQUIRE(m.translate({{0, 2}}, {0, 1, 0}).ok());
  CHECK(changed());
  REQUIRE(m.set_mesh_size({1}, 0.5).ok());
  CHECK(changed());
  REQUIRE(m.remove({{1, 1}}, false).ok());
  CHECK(changed());
  // Another model's change never reuses a value this one had.
  Model other;
  REQUIRE(other.add_point(1, {0, 0, 0}).ok());
  CHECK(std::find(seen.begin(), seen.end(), other.revision()) == seen.end());
}
