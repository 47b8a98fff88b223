#include "field/size_policy.h"

#include <numbers>

#include <doctest/doctest.h>

using namespace sm::field;

TEST_CASE("size policy: Gmsh's BGM_MeshSize combination") {
  SizePolicyOptions o;
  SizeQuery q;
  q.bbox_diag = 10;
  q.entity_dim = 2;
  CHECK(final_size(o, q).size == 10);  // nothing but the bbox
  q.background = 0.5;
  CHECK(final_size(o, q).size == 0.5);
  q.entity_dim = 0;
  q.point_lc = 0.3;
  CHECK(final_size(o, q).size == 0.3);
  q.point_lc.reset();
  q.background.reset();
  CHECK(final_size(o, q).size == 1);  // a point without size: bbox/10
  q.entity_dim = 1;
  q.end_lc0 = 0.2;
  q.end_lc1 = 0.6;
  q.t = 0.25;
  CHECK(final_size(o, q).size == doctest::Approx(0.3));
  q.end_lc1.reset();  // one missing end size interpolates toward 1e22, capped by the bbox
  CHECK(final_size(o, q).size == 10);
  o.from_points = false;
  q.end_lc1 = 0.6;
  CHECK(final_size(o, q).size == 10);
  o.from_curvature = 20;
  q.curvature = 2;
  CHECK(final_size(o, q).size == doctest::Approx(2 * std::numbers::pi / 40));
  o.min = 0.5;
  CHECK(final_size(o, q).size == 0.5);
  o.max = 0.25;  // max applied after min
  CHECK(final_size(o, q).size == 0.25);
  o.factor = 2;
  q.entity_factor = 3;
  CHECK(final_size(o, q).size == 1.5);
}

TEST_CASE("size policy: non-positive sizes fall back to the bbox and are reported") {
  SizePolicyOptions o;
  SizeQuery q;
  q.bbox_diag = 4;
  q.background = -1;
  const SizeResult r = final_size(o, q);
  CHECK(r.nonpositive);
  CHECK(r.size == 4);
  q.bbox_diag = 0;
  q.background.reset();
  CHECK(final_size(o, q).size == 1);  // degenerate box: 1
}

TEST_CASE("size policy: option names and their CharacteristicLength aliases") {
  SizePolicyOptions o;
  CHECK(set_size_option(o, "Mesh.MeshSizeMin", 0.1));
  CHECK(set_size_option(o, "CharacteristicLengthMax", 2));
  CHECK(set_size_option(o, "Mesh.CharacteristicLengthFactor", 0.5));
  CHECK(set_size_option(o, "MeshSizeFromPoints", 0));
  CHECK(set_size_option(o, "Mesh.CharacteristicLengthExtendFromBoundary", 0));
  CHECK(set_size_option(o, "MeshSizeFromCurvature", 12));
  CHECK(!set_size_option(o, "Mesh.MeshSizeMinimum", 1));
  CHECK(!set_size_option(o, "Mesh.Algorithm", 5));
  CHECK(o.min == 0.1);
  CHECK(o.max == 2);
  CHECK(o.factor == 0.5);
  CHECK(!o.from_points);
  CHECK(o.extend_from_boundary == 0);
  CHECK(o.from_curvature == 12);
  CHECK(surface_target(o, 0.7, 0.4) == 0.7);
  o.extend_from_boundary = 1;
  CHECK(surface_target(o, 0.7, 0.4) == 0.4);
  CHECK(surface_target(o, 0.7, std::nullopt) == 0.7);
}
