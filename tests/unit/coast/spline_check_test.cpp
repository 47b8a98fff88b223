// B-spline span hulls: overlap detection, and the optional refinement in the import.
#include "coast/spline_check.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/import.h"

using namespace sm;
using namespace sm::coast;

TEST_CASE("spline hulls: far loops are separate, close parallel coasts overlap") {
  const std::vector<Vec2> a{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {0, 1}};
  const std::vector<Vec2> b{{0, 3}, {3, 3}, {3, 4}, {2, 4}, {1, 4}, {0, 4}};
  std::vector<SplineLoop> loops{{a, {}, true}, {b, {}, true}};
  CHECK(find_hull_overlaps(loops).empty());
  // b's bottom now 0.2 above a's top, and a's top corner span hull (a[3], a[4], a[5], a[0])
  // is the whole rectangle: spans of different loops with overlapping hulls.
  const std::vector<Vec2> c{{0, 1.2}, {3, 1.2}, {3, 2}, {0, 2}};
  const std::vector<Vec2> d{{-1, 0.5}, {4, 0.5}, {4, 0.6}, {-1, 0.6}};   // crosses a's hull
  std::vector<SplineLoop> l2{{a, {}, true}, {d, {}, true}};
  const auto o = find_hull_overlaps(l2);
  REQUIRE_FALSE(o.empty());
  CHECK(o[0].loop_a == 0);
  CHECK(o[0].loop_b == 1);
  std::vector<SplineLoop> l3{{a, {}, true}, {c, {}, true}};
  for (const auto& h : find_hull_overlaps(l3)) CHECK(h.loop_a != h.loop_b);   // only between the loops, if any
  // Within one loop, spans sharing a control point are never compared.
  const std::vector<Vec2> tri{{0, 0}, {1, 0}, {0.5, 1}};
  std::vector<SplineLoop> l4{{tri, {}, true}};
  CHECK(find_hull_overlaps(l4).empty());
}

TEST_CASE("spline hulls: a thin U-shaped island gets its arms refined apart") {
  // A U of 1 km wide arms 2 km apart, 50 km long, sampled every ~1 km.
  Coastline c;
  Ring ant;
  for (int i = 0; i < 36; ++i) ant.pts.push_back({180.0 - 10.0 * i, -70.0});
  ant.wraps_pole = true;
  c.rings.push_back(ant);
  Ring u;
  u.record = 1;
  const double dl = 0.0141;   // 1 km of longitude at 50N
  for (int i = 0; i <= 50; ++i) u.pts.push_back({0.0 + dl * 0, 50.0 + 0.009 * i});        // left arm, outer side up
  for (int i = 50; i >= 1; --i) u.pts.push_back({dl * 1, 50.0 + 0.009 * i});             // its inner side down
  for (int i = 1; i <= 50; ++i) u.pts.push_back({dl * 3, 50.0 + 0.009 * i});             // right arm inner side up
  for (int i = 50; i >= 0; --i) u.pts.push_back({dl * 4, 50.0 + 0.009 * i});             // outer side down
  std::reverse(u.pts.begin(), u.pts.end());
  u.pts.push_back({dl * 2, 49.99});                                                         // the bottom of the U
  c.rings.push_back(u);
  ImportOptions o;
  o.gamma = [](std::span<const Vec3>, std::span<double> g) {
    for (double& x : g) x = 4000;
  };
  auto plain = build_coast_model(c, o);
  REQUIRE_MESSAGE(plain.ok(), (plain.ok() ? "" : plain.error().to_string()));
  o.check_splines = true;
  auto checked = build_coast_model(c, o);
  REQUIRE(checked.ok());
  CHECK(checked->report.count(RepairKind::SplineHull) > 0);
  CHECK(checked->report.points_out > plain->report.points_out);
  // What is left overlapping is on source data only and is reported, not hidden.
  std::vector<std::vector<Vec2>> polys;
  std::vector<SplineLoop> sl;
  for (const auto& loop : checked->loops) polys.push_back(checked->curves[loop.curves[0]].uv);
  for (const auto& p : polys) sl.push_back({p, {}, true});
  const auto left = find_hull_overlaps(sl);
  CHECK((left.empty() || checked->report.count(RepairKind::SplineMayCross) > 0));
}
