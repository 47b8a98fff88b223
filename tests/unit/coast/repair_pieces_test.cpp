// Repair of loops made of several curves (the pieces a binned or clipped source is read
// in) whose source data meets itself across the end of a piece. The full GSHHG at 3 km
// (examples/world_ocean.geo) stopped on such a place: North America comes as thousands of
// pieces cut at the bins' edges, and near 83.87W 66.70N a segment of one piece crosses a
// segment of the next; the sliver between them could only be cut within one curve.
#include "coast/repair.h"

#include <doctest/doctest.h>

#include <string>

#include "coast/intersections.h"
#include "geo/sphere.h"

using namespace sm;
using namespace sm::coast;

namespace {

// (u,v) of a shape point: a 1e-4 square (about 1 km) away from the plane's origin.
Vec2 pieces_uv(Vec2 s) { return Vec2{0.1, 0.2} + 1e-4 * s; }

// A non-periodic curve through the shape's points, all of them control points (original
// data everywhere: the refinement has nothing to put back).
WorkCurve pieces_curve(const std::vector<Vec2>& shape, bool box = false) {
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  WorkCurve c;
  for (const Vec2& s : shape) {
    c.keep.push_back(static_cast<std::uint32_t>(c.full.size()));
    c.uv.push_back(pieces_uv(s));
    c.full.push_back(ps.lonlat_from_param(c.uv.back()));
    c.gamma.push_back(1000.0);
  }
  c.open_boundary = box;
  c.record = box ? static_cast<std::size_t>(-1) : 7;
  c.id = box ? -1 : 2;
  return c;
}

// The same from (u,v) points as they are.
WorkCurve pieces_curve_uv(const std::vector<Vec2>& uv) {
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  WorkCurve c;
  for (const Vec2& p : uv) {
    c.keep.push_back(static_cast<std::uint32_t>(c.full.size()));
    c.uv.push_back(p);
    c.full.push_back(ps.lonlat_from_param(p));
    c.gamma.push_back(3000.0);
  }
  c.record = 9569;
  c.id = 2;
  return c;
}

std::vector<Vec2> pieces_shape_of(const WorkCurve& c) {
  std::vector<Vec2> s;
  for (std::uint32_t k : c.keep) s.push_back((c.uv[k] - Vec2{0.1, 0.2}) / 1e-4);
  return s;
}

void pieces_check_shape(const WorkCurve& c, const std::vector<Vec2>& want) {
  const std::vector<Vec2> got = pieces_shape_of(c);
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    CHECK(got[i].x == doctest::Approx(want[i].x).epsilon(1e-9));
    CHECK(got[i].y == doctest::Approx(want[i].y).epsilon(1e-9));
  }
  CHECK(c.full.size() == c.uv.size());
  CHECK(c.gamma.size() == c.uv.size());
  CHECK(c.keep.front() == 0);
  CHECK(c.keep.back() == c.full.size() - 1);
}

// The loop's polygon crosses itself nowhere (the repair's own test).
bool pieces_simple(const std::vector<WorkCurve>& curves, const WorkLoop& loop) {
  std::vector<std::vector<Vec2>> polys(1);
  loop_polygon(curves, loop, polys[0], nullptr);
  return find_intersections(polys).empty();
}

RepairOptions pieces_options() {
  RepairOptions o;
  o.check_splines = false;   // the polygon repair alone (the B-splines are not at issue here)
  return o;
}

std::size_t pieces_cuts(const std::vector<RepairEntry>& log) {
  std::size_t n = 0;
  for (const RepairEntry& e : log) n += e.kind == RepairKind::CutSliver;
  return n;
}

}  // namespace

// The ring (0,0) (1,0) (1,1) (0.6,1) (0.4,1.1) (0.6,1.1) (0.4,1) (0,1): its segments
// (0.6,1)->(0.4,1.1) and (0.6,1.1)->(0.4,1) cross at (0.5,1.05), a twisted sliver of two
// points (the same shape as repair_test.cpp's single-curve sliver), here cut into pieces.
TEST_CASE("repair: a sliver across the end of a piece is cut out across the two curves") {
  std::vector<WorkCurve> curves{pieces_curve({{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {0.4, 1.1}}),
                                pieces_curve({{0.4, 1.1}, {0.6, 1.1}, {0.4, 1}, {0, 1}, {0, 0}})};
  std::vector<WorkLoop> loops(1);
  loops[0].curves = {0, 1};
  std::vector<RepairEntry> log;
  auto r = repair_loops(curves, loops, pieces_options(), log);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  REQUIRE(pieces_cuts(log) == 1);
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  const geo::LonLat x = ps.lonlat_from_param(pieces_uv({0.5, 1.05}));
  for (const RepairEntry& e : log)
    if (e.kind == RepairKind::CutSliver) {
      CHECK(e.where.lon == doctest::Approx(x.lon).epsilon(1e-9));
      CHECK(e.where.lat == doctest::Approx(x.lat).epsilon(1e-9));
      CHECK(e.id == 2);
    }
  // The first piece ends on the point after the crossing, where the second now starts.
  REQUIRE(loops[0].curves == std::vector<std::uint32_t>{0, 1});
  pieces_check_shape(curves[0], {{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {0.4, 1}});
  pieces_check_shape(curves[1], {{0.4, 1}, {0, 1}, {0, 0}});
  CHECK(pieces_simple(curves, loops[0]));
}

TEST_CASE("repair: a sliver across pieces drops the pieces inside it, across the loop's start too") {
  SUBCASE("the second piece ends on the point after the crossing: it leaves the loop") {
    std::vector<WorkCurve> curves{pieces_curve({{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {0.4, 1.1}}),
                                  pieces_curve({{0.4, 1.1}, {0.6, 1.1}, {0.4, 1}}),
                                  pieces_curve({{0.4, 1}, {0, 1}, {0, 0}})};
    std::vector<WorkLoop> loops(1);
    loops[0].curves = {0, 1, 2};
    std::vector<RepairEntry> log;
    auto r = repair_loops(curves, loops, pieces_options(), log);
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
    CHECK(pieces_cuts(log) == 1);
    REQUIRE(loops[0].curves == std::vector<std::uint32_t>{0, 2});
    pieces_check_shape(curves[0], {{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {0.4, 1}});
    pieces_check_shape(curves[2], {{0.4, 1}, {0, 1}, {0, 0}});
    CHECK(pieces_simple(curves, loops[0]));
  }
  SUBCASE("the sliver holds a whole piece and runs over the loop's first curve") {
    // Loop order P0 P1 P2 P3: the crossing segments are P2's and P0's first ones; the
    // short side runs from P2 through P3 into P0 (six points the other way, two this way).
    std::vector<WorkCurve> curves{pieces_curve({{0.6, 1.1}, {0.4, 1}, {0, 1}, {0, 0}}),
                                  pieces_curve({{0, 0}, {1, 0}, {1, 1}, {0.6, 1}}),
                                  pieces_curve({{0.6, 1}, {0.4, 1.1}}),
                                  pieces_curve({{0.4, 1.1}, {0.6, 1.1}})};
    std::vector<WorkLoop> loops(1);
    loops[0].curves = {0, 1, 2, 3};
    std::vector<RepairEntry> log;
    auto r = repair_loops(curves, loops, pieces_options(), log);
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
    CHECK(pieces_cuts(log) == 1);
    REQUIRE(loops[0].curves == std::vector<std::uint32_t>{0, 1, 2});
    pieces_check_shape(curves[2], {{0.6, 1}, {0.4, 1}});
    pieces_check_shape(curves[0], {{0.4, 1}, {0, 1}, {0, 0}});
    pieces_check_shape(curves[1], {{0, 0}, {1, 0}, {1, 1}, {0.6, 1}});
    CHECK(pieces_simple(curves, loops[0]));
  }
}

TEST_CASE("repair: a sliver across pieces holding the region's box is not cut: the error stays") {
  // The middle piece is a side of the region's box (not source shoreline): cutting the
  // sliver would take the box apart, so the place is reported as before.
  std::vector<WorkCurve> curves{pieces_curve({{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {0.4, 1.1}}),
                                pieces_curve({{0.4, 1.1}, {0.6, 1.1}}, true),
                                pieces_curve({{0.6, 1.1}, {0.4, 1}, {0, 1}, {0, 0}})};
  std::vector<WorkLoop> loops(1);
  loops[0].curves = {0, 1, 2};
  loops[0].hole = false;
  std::vector<RepairEntry> log;
  auto r = repair_loops(curves, loops, pieces_options(), log);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().to_string().find("no sliver can be cut out") != std::string::npos);
  CHECK(pieces_cuts(log) == 0);
}

TEST_CASE("repair: the full GSHHG's crossing near 83.87W 66.70N, replayed, is cut across its two pieces") {
  // (u,v) of the source points as the 3 km import holds them: a0 a1 a2 one piece (a1 the
  // middle of the source segment a0 a2, put there by the deviation bound), then the next
  // piece from a2 whose segment b6 b7 crosses a1 a2 (b6 lies about 1 m across it); the
  // points between a2 and b5 are left out and a closing piece b8 a0 added. The sliver a2 b5
  // b6 is cut (three points; b7 b8 a0 a1 the other way).
  const Vec2 a0{-0.021973760598056932, 0.20497687165489364}, a1{-0.022013342882351031, 0.20501785833865482},
      a2{-0.022052925166645129, 0.205058845022416}, b5{-0.022010093668356007, 0.20502882086066074},
      b6{-0.022019938544228488, 0.20502483173178568}, b7{-0.022022908733432843, 0.20502060333237104},
      b8{-0.022019067110630518, 0.20499923528803671};
  std::vector<WorkCurve> curves{pieces_curve_uv({a0, a1, a2}), pieces_curve_uv({a2, b5, b6, b7, b8}),
                                pieces_curve_uv({b8, a0})};
  std::vector<WorkLoop> loops(1);
  loops[0].curves = {0, 1, 2};
  std::vector<RepairEntry> log;
  auto r = repair_loops(curves, loops, pieces_options(), log);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  CHECK(pieces_cuts(log) == 1);
  REQUIRE(loops[0].curves == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(curves[0].uv == std::vector<Vec2>{a0, a1, b7});
  CHECK(curves[1].uv == std::vector<Vec2>{b7, b8});
  CHECK(curves[2].uv == std::vector<Vec2>{b8, a0});
  CHECK(curves[0].keep == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(curves[1].keep == std::vector<std::uint32_t>{0, 1});
  CHECK(pieces_simple(curves, loops[0]));
}
