// geo/extrude.cpp: the layers' fractions, where an extrusion takes a point, and the entities
// Model::extrude makes (with the tags and lists checked against gmsh 4.8.4 -0 in
// tests/scripts/gmsh_compat/extrude_*.geo).
#include "geo/model.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace sm;
using namespace sm::geo;

namespace {

bool near_vec(Vec3 a, Vec3 b) { return norm(a - b) < 1e-12; }

}  // namespace

TEST_CASE("extrude layers: one node per element at the cumulative heights") {
  ExtrudeLayers l;
  l.elements = {2, 3};
  l.heights = {0.5, 1.0};
  const std::vector<double> f = l.fractions();
  REQUIRE(f.size() == 6);
  CHECK(f[0] == 0.0);
  CHECK(f[1] == doctest::Approx(0.25));
  CHECK(f[2] == doctest::Approx(0.5));
  CHECK(f[3] == doctest::Approx(0.5 + 0.5 / 3));
  CHECK(f[5] == doctest::Approx(1.0));
}

TEST_CASE("extrude_point: translation, rotation about an axis through a point, twist") {
  ExtrudeSpec t;
  t.translation = {0, 0, 2};
  CHECK(near_vec(extrude_point(t, {1, 1, 0}, 0.5), {1, 1, 1}));
  ExtrudeSpec r;
  r.kind = ExtrudeKind::Rotate;
  r.axis = {0, 0, 1};
  r.point = {1, 0, 0};
  r.angle = std::acos(-1.0);
  CHECK(near_vec(extrude_point(r, {2, 0, 5}, 1.0), {0, 0, 5}));
  CHECK(near_vec(extrude_point(r, {2, 0, 5}, 0.5), {1, 1, 5}));
  ExtrudeSpec w = r;
  w.kind = ExtrudeKind::Twist;
  w.translation = {0, 0, 4};
  CHECK(near_vec(extrude_point(w, {2, 0, 0}, 0.5), {1, 1, 2}));
}

TEST_CASE("Model::extrude of a curve: top, surface, lateral curves; a rotation about an end makes a triangle") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.1));
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.1));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  ExtrudeSpec t;
  t.translation = {0, 1, 0};
  t.layered = true;
  t.layers.elements = {4};
  t.layers.heights = {1};
  auto r = m.extrude({{1, 1}}, t);
  REQUIRE(r);
  REQUIRE(r->size() == 4);
  const int top = (*r)[0].tag, surface = (*r)[1].tag;
  CHECK((*r)[1].dim == 2);
  REQUIRE(m.surface(surface));
  CHECK_FALSE(m.surface(surface)->filling);   // flat: a plane surface
  const Extrusion* e = m.extrusion(2, surface);
  REQUIRE(e);
  CHECK(e->body);
  CHECK(e->source == 1);
  CHECK(e->top == top);
  CHECK(e->begin_curve != 0);
  CHECK(e->end_curve != 0);
  const Extrusion* te = m.extrusion(1, top);
  REQUIRE(te);
  CHECK_FALSE(te->body);

  ExtrudeSpec rot;
  rot.kind = ExtrudeKind::Rotate;
  rot.axis = {0, 0, 1};
  rot.angle = std::acos(-1.0) / 2;
  auto q = m.extrude({{1, 1}}, rot);
  REQUIRE(q);
  REQUIRE(q->size() == 3);   // top, surface, one lateral arc (point 1 is on the axis)
  const Extrusion* qe = m.extrusion(2, (*q)[1].tag);
  REQUIRE(qe);
  CHECK(qe->begin_curve == 0);
  CHECK(m.curve(std::abs((*q)[2].tag))->kind == CurveKind::Circle);
}

TEST_CASE("Model::extrude of a surface makes a volume; Surface Loop and Volume check their members") {
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {1, 0, 0}));
  REQUIRE(m.add_point(3, {0, 1, 0}));
  REQUIRE(m.add_curve(1, CurveKind::Line, {1, 2}));
  REQUIRE(m.add_curve(2, CurveKind::Line, {2, 3}));
  REQUIRE(m.add_curve(3, CurveKind::Line, {3, 1}));
  REQUIRE(m.add_curve_loop(4, {1, 2, 3}));
  REQUIRE(m.add_plane_surface(5, {4}));
  ExtrudeSpec t;
  t.translation = {0, 0, 1};
  auto r = m.extrude({{2, 5}}, t);
  REQUIRE(r);
  REQUIRE(r->size() == 5);   // top, volume, three lateral surfaces
  CHECK((*r)[1].dim == 3);
  CHECK(m.volumes().count((*r)[1].tag) == 1);
  CHECK(m.volumes().at((*r)[1].tag).surfaces.size() == 5);
  CHECK_FALSE(m.add_surface_loop(100, {5, 999}));
  REQUIRE(m.add_surface_loop(100, {5}));
  CHECK_FALSE(m.add_volume(101, {7}));
  CHECK(m.add_volume(101, {100}));
  CHECK_FALSE(m.extrude({{3, 101}}, t));   // volumes are not extruded
}
