// The words of each MeshNote kind (interp/kernel/mesh_note_words.cpp): the sentences the
// mesher's warnings had when the kernel wrote them, now from typed values.
#include <doctest/doctest.h>

#include <string>

#include "interp/kernel/mesh_note_words.h"
#include "lang/source.h"

namespace {

struct NoteWords {
  std::string kebab, message;
};

NoteWords note_words(const sm::MeshNote& note, const sm::CompoundSurfacePlan& compounds = {}) {
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  sm::interp::report_mesh_note(diags, sm::lang::SourceRange{}, note, compounds);
  REQUIRE(diags.all().size() == 1);
  CHECK(diags.all()[0].severity == sm::lang::Severity::Warning);
  return {std::string(sm::lang::diag_info(diags.all()[0].kind).kebab), diags.all()[0].message};
}

sm::MeshPlace flat_place(double x, double y, double z) { return {.xyz = {x, y, z}}; }
sm::MeshPlace sphere_place(double lon, double lat) { return {.on_sphere = true, .lonlat = {lon, lat}}; }

}  // namespace

TEST_CASE("mesh note words: islands, one or several, the first eight loops listed") {
  sm::MeshNote one{.kind = sm::MeshNoteKind::IslandsLeftOut, .surface = 4, .place = sphere_place(-3.25, 51.5)};
  one.loops = {7};
  const NoteWords r1 = note_words(one);
  CHECK(r1.kebab == "mesh-warning");
  CHECK(r1.message ==
        "surface 4: 1 island smaller than the mesh size is left out (its closed curve got fewer than 3 mesh edges; "
        "near lon -3.2500, lat 51.5000): hole loop 7");
  sm::MeshNote many{.kind = sm::MeshNoteKind::IslandsLeftOut, .surface = 1, .place = flat_place(0.7, 0.3, 0)};
  for (int l = 2; l <= 12; ++l) many.loops.push_back(l);
  CHECK(note_words(many).message ==
        "surface 1: 11 islands smaller than the mesh size are left out (their closed curves got fewer than 3 mesh "
        "edges; largest near (0.7, 0.3, 0)): hole loops 2, 3, 4, 5, 6, 7, 8, 9 and 3 more");
}

TEST_CASE("mesh note words: a boundary off its plane, and a Compound Surface's union named") {
  sm::CompoundSurfacePlan plan;
  plan.groups.push_back({.union_tag = 9, .surfaces = {1, 2}});
  const sm::MeshNote off{.kind = sm::MeshNoteKind::BoundaryOffPlane,
                         .surface = 9,
                         .place = flat_place(0, 0, 0),
                         .distance = 2.5e-5,
                         .relative = 1.77e-5};
  const NoteWords r = note_words(off, plan);
  CHECK(r.kebab == "mesh-warning");
  CHECK(r.message ==
        "the union of Compound Surface{1, 2}: the boundary lies up to 2.5e-05 off the surface's plane (more than "
        "Geometry.Tolerance; 1.8e-05 of its size) near (0, 0, 0): meshed in that plane, as Gmsh meshes a Plane "
        "Surface in its mean plane");
  // Surface 90 is no union: "surface 9" inside "surface 90" is not renamed.
  sm::MeshNote other = off;
  other.surface = 90;
  CHECK(note_words(other, plan).message.rfind("surface 90: the boundary", 0) == 0);
}

TEST_CASE("mesh note words: a declined Compound Surface group") {
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  sm::interp::report_compound_declined(diags, sm::lang::SourceRange{},
                                       {{1, 2, 5}, "they have no boundary of their own"});
  REQUIRE(diags.all().size() == 1);
  CHECK(diags.all()[0].message ==
        "Compound Surface{1, 2, 5}: they have no boundary of their own; the surfaces are meshed one by one");
}

TEST_CASE("mesh note words: the quality floor's five sentences") {
  sm::MeshNote sharp{.kind = sm::MeshNoteKind::FloorSharpCorners,
                     .surface = 1,
                     .count = 1,
                     .floor = 0.3,
                     .sharp_limit_degrees = 9.44};
  for (int i = 0; i < 9; ++i) sharp.corners.push_back({5.0 + i, flat_place(i, 0, 0)});
  const NoteWords r = note_words(sharp);
  CHECK(r.kebab == "mesh-quality-floor");
  CHECK(r.message ==
        "surface 1: 1 triangle below Mesh.QualityFloor = 0.3 where the boundary makes an angle too sharp for it (under "
        "9.4 degrees): 5.0 degrees at (0, 0, 0); 6.0 degrees at (1, 0, 0); 7.0 degrees at (2, 0, 0); 8.0 degrees at "
        "(3, 0, 0); 9.0 degrees at (4, 0, 0); 10.0 degrees at (5, 0, 0); 11.0 degrees at (6, 0, 0); 12.0 degrees at "
        "(7, 0, 0); and 1 more");

  sm::MeshNote below{.kind = sm::MeshNoteKind::FloorStillBelow,
                     .surface = 3,
                     .place = sphere_place(10, -20.5),
                     .count = 20,
                     .floor = 0.3,
                     .rounds = 1,
                     .new_points = 0,
                     .worst_rho = 0.18912};
  CHECK(note_words(below).message ==
        "surface 3: 20 triangles still below Mesh.QualityFloor = 0.3 after 1 round and 0 new points (the work is "
        "bounded); the worst, rho 0.1891, near lon 10.0000, lat -20.5000");
  below.count = 1, below.rounds = 4, below.new_points = 120, below.work_budget = 5000;
  CHECK(note_words(below).message ==
        "surface 3: 1 triangle still below Mesh.QualityFloor = 0.3 after 4 rounds and 120 new points (the work is "
        "bounded: its budget of 5000 operations ran out); the worst, rho 0.1891, near lon 10.0000, lat -20.5000");

  const sm::MeshNote put_back{.kind = sm::MeshNoteKind::FloorPutBack,
                              .surface = 2,
                              .count = 7,
                              .count_before = 5,
                              .floor = 0.25,
                              .rounds = 2,
                              .new_points = 31};
  CHECK(note_words(put_back).message ==
        "surface 2: Mesh.QualityFloor = 0.25 left 7 triangles below it where the face had 5 (after 2 rounds and 31 "
        "new points); the face is left as it was before the floor");

  sm::MeshNote fault{.kind = sm::MeshNoteKind::FloorFault, .surface = 2, .place = flat_place(0.5, 0.25, 0)};
  fault.fault = "the walk round a vertex of the quality floor did not end";
  CHECK(note_words(fault).message ==
        "surface 2: internal error: the walk round a vertex of the quality floor did not end near (0.5, 0.25, 0); the "
        "face is left as it was before Mesh.QualityFloor");
}
