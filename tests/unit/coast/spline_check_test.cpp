// B-spline span hulls and the precise crossing test (find_spline_crossings), checked against
// an independent one: the curves as geo/curve_bspline.h evaluates them, sampled densely and
// tested for segment intersections with exact predicates; the repair in the import.
#include "coast/spline_check.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/import.h"
#include "coast/intersections.h"
#include "coast/loop_uv.h"
#include "coast/place_pairs.h"
#include "coast/read_lonlat_text.h"
#include "geo/curve_bspline.h"

using namespace sm;
using namespace sm::coast;

namespace {

// One loop's curves sampled: per_span points per B-spline span, as Gmsh draws them
// (periodic: wrapping; pieces: end points tripled, each ending where the next starts).
std::vector<Vec2> sample_loop(std::span<const std::vector<Vec2>> curves, bool periodic, int per_span) {
  std::vector<Vec2> poly;
  for (const auto& c : curves) {
    std::vector<Vec2> ctrl = c;
    if (periodic) ctrl.push_back(c[0]);
    const int pieces = periodic ? static_cast<int>(ctrl.size()) - 1 : static_cast<int>(ctrl.size()) + 1;
    for (int i = 0; i < pieces * per_span; ++i)
      poly.push_back(geo::eval_bspline_uniform(std::span<const Vec2>(ctrl), periodic,
                                               static_cast<double>(i) / (pieces * per_span)).p);
  }
  return poly;
}

// Crossings of the sampled B-splines of every loop of an imported model.
std::vector<SegmentHit> sampled_crossings(const CoastModel& m, int per_span = 32) {
  std::vector<std::vector<Vec2>> polys;
  for (const CoastLoop& loop : m.loops) {
    std::vector<std::vector<Vec2>> curves;
    bool periodic = false;
    for (std::uint32_t ci : loop.curves) {
      curves.push_back(m.curves[ci].uv);
      periodic = m.curves[ci].periodic;
    }
    polys.push_back(sample_loop(curves, periodic && loop.curves.size() == 1, per_span));
  }
  return find_intersections(polys);
}

std::vector<SegmentHit> sampled_crossings(std::span<const std::vector<Vec2>> periodic_loops, int per_span = 64) {
  std::vector<std::vector<Vec2>> polys;
  for (const auto& l : periodic_loops) polys.push_back(sample_loop(std::span(&l, 1), true, per_span));
  return find_intersections(polys);
}

// The L-shaped loop: its spline cuts the reflex corner (2,2) through (7/3, 7/3), outside
// the polygon.
const std::vector<Vec2> kL{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};

std::vector<Vec2> square(Vec2 c, double h) {
  return {{c.x - h, c.y - h}, {c.x + h, c.y - h}, {c.x + h, c.y + h}, {c.x - h, c.y + h}};
}

}  // namespace

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

TEST_CASE("spline crossings: a thin U-shaped island whose arms' hulls overlap is left alone") {
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
  o.repair.check_splines = false;
  auto plain = build_coast_model(c, o);
  REQUIRE_MESSAGE(plain.ok(), (plain.ok() ? "" : plain.error().to_string()));
  // The arms' span hulls overlap, yet the curves keep apart: nothing to repair.
  std::vector<SplineLoop> sl;
  for (const auto& loop : plain->loops) sl.push_back({plain->curves[loop.curves[0]].uv, {}, true});
  REQUIRE_FALSE(find_hull_overlaps(sl).empty());
  REQUIRE(sampled_crossings(*plain).empty());
  o.repair.check_splines = true;
  auto checked = build_coast_model(c, o);
  REQUIRE(checked.ok());
  CHECK(checked->report.count(RepairKind::SplineHull) == 0);
  CHECK(checked->report.points_out == plain->report.points_out);
}

TEST_CASE("spline crossings: control polygons apart, curves crossing, found exactly there") {
  // A small square in the L's notch: its polygon is outside the L, but the L's spline runs
  // through the square's centre.
  const std::vector<std::vector<Vec2>> loops{kL, square({7.0 / 3, 7.0 / 3}, 0.03)};
  REQUIRE(find_intersections(loops).empty());        // the polygons do not meet
  REQUIRE_FALSE(sampled_crossings(loops).empty());   // the curves do
  std::vector<SplineLoop> sl{{loops[0], {}, true}, {loops[1], {}, true}};
  const auto x = find_spline_crossings(sl);
  REQUIRE_FALSE(x.empty());
  for (const auto& o : x) {
    CHECK(o.loop_a == 0);
    CHECK(o.loop_b == 1);
    CHECK((o.seg_a == 2 || o.seg_a == 3));   // the L's spans round the reflex corner (2,2)
    CHECK(norm(o.where - Vec2{7.0 / 3, 7.0 / 3}) < 0.1);
  }
}

TEST_CASE("spline crossings: with some spans marked active, exactly the full search's pairs holding one") {
  const std::vector<std::vector<Vec2>> loops{kL, square({7.0 / 3, 7.0 / 3}, 0.03)};
  std::vector<SplineLoop> sl{{loops[0], {}, true}, {loops[1], {}, true}};
  const auto full = find_spline_crossings(sl);
  REQUIRE_FALSE(full.empty());
  std::vector<std::vector<char>> active{std::vector<char>(loops[0].size(), 0), std::vector<char>(loops[1].size(), 0)};
  sl[0].active = active[0];
  sl[1].active = active[1];
  CHECK(find_spline_crossings(sl).empty());   // nothing marked: nothing tested
  std::size_t found = 0;
  for (std::uint32_t l = 0; l < 2; ++l)
    for (std::uint32_t s = 0; s < loops[l].size(); ++s) {
      active[l][s] = 1;
      std::vector<HullOverlap> expect;
      for (const HullOverlap& o : full)
        if ((o.loop_a == l && o.seg_a == s) || (o.loop_b == l && o.seg_b == s)) expect.push_back(o);
      const auto got = find_spline_crossings(sl);
      REQUIRE(got.size() == expect.size());
      for (std::size_t i = 0; i < got.size(); ++i) {
        CHECK(place_pair_key(got[i]) == place_pair_key(expect[i]));
        CHECK(got[i].where == expect[i].where);
      }
      found += got.size();
      active[l][s] = 0;
    }
  CHECK(found == 2 * full.size());   // each pair through either of its spans
}

TEST_CASE("spline crossings: spans made only near the active ones, on any number of threads, as the full search") {
  // A comb of 40 teeth (160 points: many blocks of segments) whose spline cuts each reflex
  // corner at the notch's bottom as the L's does, a small square on each cut.
  constexpr int kTeeth = 40;
  std::vector<std::vector<Vec2>> loops(1);
  std::vector<Vec2> comb{{0, 0}, {4.0 * kTeeth - 2, 0}, {4.0 * kTeeth - 2, 4}};
  for (int k = kTeeth - 1; k >= 1; --k) {
    const double x = 4.0 * k;
    comb.insert(comb.end(), {{x, 4}, {x, 2}, {x - 2, 2}, {x - 2, 4}});
    loops.push_back(square({x - 2 + 1.0 / 3, 2 + 1.0 / 3}, 0.03));
  }
  comb.push_back({0, 4});
  loops[0] = std::move(comb);
  REQUIRE(find_intersections(loops).empty());
  std::vector<SplineLoop> sl;
  for (const auto& l : loops) sl.push_back({l, {}, true});
  const auto full = find_spline_crossings(sl);
  REQUIRE(full.size() >= kTeeth - 1);   // every square crossed
  const auto two = find_spline_crossings(sl, 2);
  REQUIRE(two.size() == full.size());
  for (std::size_t i = 0; i < full.size(); ++i) {
    CHECK(place_pair_key(two[i]) == place_pair_key(full[i]));
    CHECK(two[i].where == full[i].where);
  }
  // A few comb segments and every third square active: the full search's pairs holding one.
  std::vector<std::vector<char>> active(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    active[l].assign(loops[l].size(), 0);
    for (std::size_t s = 0; s < loops[l].size(); ++s) active[l][s] = l == 0 ? s % 29 == 5 : l % 3 == 0;
    sl[l].active = active[l];
  }
  auto is_active = [&](std::uint32_t l, std::uint32_t s) { return active[l][s] != 0; };
  std::vector<HullOverlap> expect;
  for (const HullOverlap& o : full)
    if (is_active(o.loop_a, o.seg_a) || is_active(o.loop_b, o.seg_b)) expect.push_back(o);
  REQUIRE_FALSE(expect.empty());
  REQUIRE(expect.size() < full.size());
  for (int threads : {1, 2}) {
    const auto got = find_spline_crossings(sl, threads);
    REQUIRE(got.size() == expect.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      CHECK(place_pair_key(got[i]) == place_pair_key(expect[i]));
      CHECK(got[i].where == expect[i].where);
    }
  }
}

TEST_CASE("spline crossings: a near miss with overlapping hulls is not a crossing") {
  // The square moved out of the notch until its spline (a rounded square, corners 2h/3 from
  // its centre) clears the L's spline by about 0.02: the span hulls still overlap.
  const double h = 0.05;
  const Vec2 c{7.0 / 3 + 2 * h / 3 + 0.015, 7.0 / 3 + 2 * h / 3 + 0.015};
  const std::vector<std::vector<Vec2>> loops{kL, square(c, h)};
  REQUIRE(sampled_crossings(loops, 256).empty());
  std::vector<SplineLoop> sl{{loops[0], {}, true}, {loops[1], {}, true}};
  REQUIRE_FALSE(find_hull_overlaps(sl).empty());
  CHECK(find_spline_crossings(sl).empty());
  // Closer than the tolerance counts as meeting.
  std::vector<double> tol0(loops[0].size(), 0.04), tol1(loops[1].size(), 0.04);
  sl[0].tol = tol0;
  sl[1].tol = tol1;
  CHECK_FALSE(find_spline_crossings(sl).empty());
}

TEST_CASE("spline crossings: joints of consecutive spans and pieces are not crossings, a loop in one span is") {
  std::vector<Vec2> oct;
  for (int i = 0; i < 8; ++i) oct.push_back({std::cos(i * 0.785398), std::sin(i * 0.785398)});
  std::vector<SplineLoop> one{{oct, {}, true}};
  CHECK(find_spline_crossings(one).empty());
  // The same points as 4 pieces (a region loop): corners where pieces meet at 90 degrees.
  const std::vector<Vec2> box{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const std::vector<std::uint32_t> starts{0, 2, 4, 6};
  std::vector<SplineLoop> pieces{{box, starts, false}};
  CHECK(find_spline_crossings(pieces).empty());
  // A piece folding back along the next one at their joint: a real overlap.
  const std::vector<Vec2> fold{{0, 0}, {1, 0}, {2, 0}, {1, 1e-9}, {0.5, 1}};
  const std::vector<std::uint32_t> fold_starts{0, 2};
  std::vector<SplineLoop> folded{{fold, fold_starts, false}};
  CHECK_FALSE(find_spline_crossings(folded).empty());
  // One span making a loop: points 0..3 give span 1 the Bezier (6, 1/6), (10/3, 0), (20/3, 0),
  // (4, 1/6), symmetric about x = 5, dipping below x = 5 and back: it crosses itself.
  const std::vector<Vec2> z{{26, 1}, {0, 0}, {10, 0}, {-16, 1}, {-16, 20}, {26, 20}};
  std::vector<SplineLoop> zl{{z, {}, true}};
  bool self = false;
  for (const auto& o : find_spline_crossings(zl))
    self |= o.loop_a == 0 && o.loop_b == 0 && o.seg_a == 1 && o.seg_b == 1;
  CHECK(self);
}

TEST_CASE("spline crossings: the import repairs a pair on original points by splitting control segments") {
  // The L and the square in lon/lat near 10E 50N, every point kept (spacing > gamma):
  // only new control points on the original segments can pull the L's spline back.
  Coastline c;
  Ring ant;
  for (int i = 0; i < 36; ++i) ant.pts.push_back({180.0 - 10.0 * i, -70.0});
  ant.wraps_pole = true;
  c.rings.push_back(ant);
  auto to_ll = [](Vec2 p) { return geo::LonLat{10.0 + 0.02 * p.x, 50.0 + 0.02 * p.y}; };
  Ring l, sq;
  l.record = 1;
  sq.record = 2;
  for (Vec2 p : kL) l.pts.push_back(to_ll(p));
  for (Vec2 p : square({7.0 / 3, 7.0 / 3}, 0.06)) sq.pts.push_back(to_ll(p));
  c.rings.push_back(l);
  c.rings.push_back(sq);
  ImportOptions o;
  o.gamma = [](std::span<const Vec3>, std::span<double> g) {
    for (double& x : g) x = 100;
  };
  // The curves as coarsening leaves them: the deviation bound's split points would pull
  // the L's spline back before the check does.
  o.deviation.factor = 0;
  o.repair.check_splines = false;
  auto plain = build_coast_model(c, o);
  REQUIRE_MESSAGE(plain.ok(), (plain.ok() ? "" : plain.error().to_string()));
  REQUIRE_FALSE(sampled_crossings(*plain).empty());
  o.repair.check_splines = true;
  auto checked = build_coast_model(c, o);
  REQUIRE(checked.ok());
  CHECK(checked->report.count(RepairKind::SplineHull) > 0);
  CHECK(checked->report.count(RepairKind::SplineMayCross) == 0);
  CHECK(checked->report.points_out > plain->report.points_out);
  CHECK(checked->report.points_out < plain->report.points_out + 40);
  CHECK(sampled_crossings(*checked).empty());
  // No repair rounds allowed: the crossing is reported with its place, not hidden.
  o.repair.max_rounds = 0;
  auto unrepaired = build_coast_model(c, o);
  REQUIRE(unrepaired.ok());
  REQUIRE(unrepaired->report.count(RepairKind::SplineMayCross) == 1);
  for (const RepairEntry& e : unrepaired->report.repair)
    if (e.kind == RepairKind::SplineMayCross) {
      CHECK(e.where.lon == doctest::Approx(10.0 + 0.02 * 7.0 / 3).epsilon(1e-3));
      CHECK(e.where.lat == doctest::Approx(50.0 + 0.02 * 7.0 / 3).epsilon(1e-3));
    }
}

TEST_CASE("spline crossings: real coastlines import with no two B-splines crossing") {
  auto gamma_of = [](double m) {
    return [m](std::span<const Vec3>, std::span<double> g) {
      for (double& x : g) x = m;
    };
  };
  struct Case {
    const char* file;
    double gamma;
    bool crossed_before;   // the unchecked import's splines cross
  };
  // world_c at 30 km: an island at the Amazon mouth (50.57W 1.56S) whose spline crosses the
  // mainland's through original points; at 50 km the Chilean fjords (72.9W 51.7S);
  // gb_ireland_f at 1 km: the Severn (2.36W 51.79N), where Gmsh's 1D mesh then crosses.
  for (const Case& k : {Case{"world_c.txt", 30000, true}, Case{"world_c.txt", 50000, true},
                        Case{"gb_ireland_f.txt", 15000, false}, Case{"gb_ireland_f.txt", 1000, true}}) {
    CAPTURE(k.file);
    CAPTURE(k.gamma);
    auto data = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/" + k.file);
    REQUIRE(data.ok());
    ImportOptions o;
    o.gamma = gamma_of(k.gamma);
    // The curves as coarsening leaves them (the deviation bound's points put back also
    // take the Chilean fjords' crossing at 50 km away): what the check is for.
    o.deviation.factor = 0;
    o.repair.check_splines = false;
    auto plain = build_coast_model(*data, o);
    REQUIRE(plain.ok());
    CHECK(sampled_crossings(*plain).empty() != k.crossed_before);
    o.repair.check_splines = true;
    auto checked = build_coast_model(*data, o);
    REQUIRE(checked.ok());
    CHECK(sampled_crossings(*checked).empty());
    CHECK(checked->report.count(RepairKind::SplineMayCross) == 0);
    // A few per cent more control points at most.
    CHECK(static_cast<double>(checked->report.points_out) < 1.03 * static_cast<double>(plain->report.points_out));
  }
}

TEST_CASE("spline crossings: the same finds on 1, 2 and 3 threads on real data (spans made in chunks of loops)") {
  // world_c at 30 km as coarsening leaves it: an island whose spline crosses the mainland's
  // (above), among hundreds of loops, so the spans are made in many chunks of loops, each
  // loop's at the place its count before gives it.
  auto data = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(data.ok());
  ImportOptions o;
  o.gamma = [](std::span<const Vec3>, std::span<double> g) {
    for (double& x : g) x = 30000;
  };
  o.deviation.factor = 0;
  o.repair.check_splines = false;
  auto plain = build_coast_model(*data, o);
  REQUIRE(plain.ok());
  std::vector<std::vector<Vec2>> polys;
  for (std::uint32_t l = 0; l < plain->loops.size(); ++l) polys.push_back(sm::testing::loop_uv(*plain, l));
  REQUIRE(polys.size() > 4 * 4);   // find_spline_crossings takes 4 loops a chunk
  std::vector<SplineLoop> sl;
  for (const auto& p : polys) sl.push_back({p, {}, true});
  auto same = [](const std::vector<HullOverlap>& a, const std::vector<HullOverlap>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      CHECK(place_pair_key(a[i]) == place_pair_key(b[i]));
      CHECK(a[i].where == b[i].where);
    }
  };
  const auto one = find_spline_crossings(sl, 1);
  REQUIRE_FALSE(one.empty());
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    same(find_spline_crossings(sl, threads), one);
  }
  // Only every third loop tested: the spans made only near them, at their places.
  std::vector<std::vector<char>> active(sl.size());
  for (std::size_t l = 0; l < sl.size(); ++l) {
    active[l].assign(polys[l].size(), l % 3 == 0 ? 1 : 0);
    sl[l].active = active[l];
  }
  const auto some = find_spline_crossings(sl, 1);
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    same(find_spline_crossings(sl, threads), some);
  }
}
