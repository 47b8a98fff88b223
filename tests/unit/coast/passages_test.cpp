// Passage closing (MinChannelWidth), dams by hand and SeaAt through the whole import, on
// synthetic rings near the equator in the region box {-1, 1, -1, 1} (degrees).
#include "coast/passages.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>

#include "coast/constant_accuracy.h"
#include "coast/loop_uv.h"
#include "coast/import.h"
#include "coast/intersections.h"
#include "coast/read_lonlat_text.h"
#include "exact/ring.h"
#include "geo/curve_bspline.h"

using namespace sm;
using namespace sm::coast;

namespace {

constexpr double kPassW = 0.01;   // degrees: the narrow water of every test, about 1112 m

// Appends the points from a to b (excluded) every `step` degrees.
void pass_line(std::vector<geo::LonLat>& out, geo::LonLat a, geo::LonLat b, double step = 0.02) {
  const double len = std::hypot(b.lon - a.lon, b.lat - a.lat);
  const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
  for (int i = 0; i < n; ++i) out.push_back({a.lon + (b.lon - a.lon) * i / n, a.lat + (b.lat - a.lat) * i / n});
}

Ring pass_ring(const std::vector<geo::LonLat>& corners, std::int64_t id) {
  Ring r;
  for (std::size_t i = 0; i < corners.size(); ++i) pass_line(r.pts, corners[i], corners[(i + 1) % corners.size()]);
  r.id = id;
  r.record = static_cast<std::size_t>(id);
  return r;
}

// A wall of land across the box (lon -0.2 .. 0.2) cut by an east-west canal of width w at
// lat 0: the south and north walls are two rings, both cut by the box.
Coastline pass_canal(double w) {
  Coastline c;
  c.file = "canal";
  c.rings.push_back(pass_ring({{-0.2, -2}, {0.2, -2}, {0.2, -w / 2}, {-0.2, -w / 2}}, 0));
  c.rings.push_back(pass_ring({{-0.2, w / 2}, {0.2, w / 2}, {0.2, 2}, {-0.2, 2}}, 1));
  return c;
}

ImportOptions pass_options(double min_width) {
  ImportOptions o;
  o.gamma = testing::constant_accuracy(300);
  o.region = LonLatBox{-1, 1, -1, 1};
  o.passages.min_width = min_width;
  return o;
}

// The surface whose water holds (lon, lat), or -1.
int pass_sea_of(const CoastModel& m, geo::LonLat ll) {
  const Vec2 uv = geo::PolarSphere({0, 0, 0}, 1.0).param_from_lonlat(ll);
  for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
    if (!point_in_ring(testing::loop_uv(m, m.surfaces[s].outer), uv)) continue;
    bool in_hole = false;
    for (std::uint32_t h : m.surfaces[s].holes) in_hole = in_hole || point_in_ring(testing::loop_uv(m, h), uv);
    if (!in_hole) return static_cast<int>(s);
  }
  return -1;
}

void pass_check_clean(const CoastModel& m) {
  std::vector<std::vector<Vec2>> polys;
  for (std::uint32_t l = 0; l < m.loops.size(); ++l) polys.push_back(testing::loop_uv(m, l));
  CHECK(find_intersections(polys).empty());
  for (const CoastSurface& s : m.surfaces) {
    CHECK(ring_orientation(polys[s.outer]) == Sign::Positive);
    for (std::uint32_t h : s.holes) CHECK(ring_orientation(polys[h]) == Sign::Negative);
  }
}

// Curve points strictly inside the box lon (lon_lo, lon_hi), lat (lat_lo, lat_hi): water left
// where a passage was filled.
std::size_t pass_points_in_box(const CoastModel& m, double lon_lo, double lon_hi, double lat_lo, double lat_hi) {
  std::size_t n = 0;
  for (const CoastCurve& c : m.curves)
    for (geo::LonLat p : c.ll) n += p.lon > lon_lo && p.lon < lon_hi && p.lat > lat_lo && p.lat < lat_hi;
  return n;
}

// The same in lon (lo, hi), lat (-half, half): water left in the canal.
std::size_t pass_points_in(const CoastModel& m, double lo, double hi, double half) {
  return pass_points_in_box(m, lo, hi, -half, half);
}

// The narrowest (vertex, facing segment) distance of the canal, as the kernel measures it.
double pass_canal_width(double w) {
  const Coastline c = pass_canal(w);
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  auto side = [&](const Ring& r, double lat) {
    std::vector<Vec2> uv;
    for (geo::LonLat p : r.pts)
      if (p.lat == lat && std::abs(p.lon) <= 0.2) uv.push_back(ps.param_from_lonlat(p));
    return uv;
  };
  const auto s = side(c.rings[0], -w / 2), n = side(c.rings[1], w / 2);
  double best = 1e300;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = 0; j + 1 < n.size(); ++j)
      best = std::min(best, uv_point_segment_metres(s[i], n[j], n[j + 1], geo::kEarthRadius));
  for (std::size_t i = 0; i < n.size(); ++i)
    for (std::size_t j = 0; j + 1 < s.size(); ++j)
      best = std::min(best, uv_point_segment_metres(n[i], s[j], s[j + 1], geo::kEarthRadius));
  return best;
}

}  // namespace

TEST_CASE("passages: without MinChannelWidth the canal stays one sea") {
  auto m = build_coast_model(pass_canal(kPassW), pass_options(0));
  REQUIRE(m.ok());
  CHECK(m->surfaces.size() == 1);
  CHECK(m->report.count(RepairKind::ClosedPassage) == 0);
  CHECK(pass_points_in(*m, -0.15, 0.15, kPassW / 2 + 1e-9) > 0);
}

TEST_CASE("passages: a canal narrower than W is closed and filled to its mouths: two seas") {
  auto m = build_coast_model(pass_canal(kPassW), pass_options(1500));
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->surfaces.size() == 2);
  CHECK(m->report.count(RepairKind::ClosedPassage) >= 1);
  const int west = pass_sea_of(*m, {-0.6, 0.5}), east = pass_sea_of(*m, {0.6, 0.5});
  CHECK(west >= 0);
  CHECK(east >= 0);
  CHECK(west != east);
  // No coast point left along the canal beyond a segment (0.02 degrees) from its mouths.
  CHECK(pass_points_in(*m, -0.2 + 0.045, 0.2 - 0.045, kPassW / 2 + 1e-9) == 0);
  // Each closure's width was reported, below W and about the canal's.
  for (const RepairEntry& e : m->report.repair)
    if (e.kind == RepairKind::ClosedPassage) {
      CHECK(e.value < 1500);
      CHECK(e.value > 1000);
    }
}

TEST_CASE("passages: a passage exactly W wide stays open; a hair narrower is closed") {
  const double width = pass_canal_width(kPassW);
  CHECK(width == doctest::Approx(kPassW * M_PI / 180 * geo::kEarthRadius).epsilon(1e-3));
  auto open = build_coast_model(pass_canal(kPassW), pass_options(width));
  REQUIRE(open.ok());
  CHECK(open->surfaces.size() == 1);
  CHECK(open->report.count(RepairKind::ClosedPassage) == 0);
  auto closed = build_coast_model(pass_canal(kPassW), pass_options(width * (1 + 1e-6)));
  REQUIRE(closed.ok());
  CHECK(closed->surfaces.size() == 2);
}

TEST_CASE("passages: a strait between two islands narrower than W merges them") {
  Coastline c;
  c.file = "islands";
  c.rings.push_back(pass_ring({{-0.5, -0.3}, {-kPassW / 2, -0.3}, {-kPassW / 2, 0.3}, {-0.5, 0.3}}, 0));
  c.rings.push_back(pass_ring({{kPassW / 2, -0.3}, {0.5, -0.3}, {0.5, 0.3}, {kPassW / 2, 0.3}}, 1));
  auto kept = build_coast_model(c, pass_options(0));
  REQUIRE(kept.ok());
  REQUIRE(kept->surfaces.size() == 1);
  CHECK(kept->surfaces[0].holes.size() == 2);
  auto m = build_coast_model(c, pass_options(1500));
  REQUIRE(m.ok());
  pass_check_clean(*m);
  REQUIRE(m->surfaces.size() == 1);
  CHECK(m->surfaces[0].holes.size() == 1);
  CHECK(m->report.count(RepairKind::ClosedPassage) >= 1);
  // The strait is land along its whole length but its ends.
  const double lon_half = kPassW / 2 - 1e-9, lat_half = 0.3 - 0.045;
  CHECK(pass_points_in_box(*m, -lon_half, lon_half, -lat_half, lat_half) == 0);
}

TEST_CASE("passages: a dead-end inlet narrower than W is closed at its mouth") {
  Coastline c;
  c.file = "inlet";
  const double h = kPassW / 2;
  c.rings.push_back(pass_ring({{-2, -2}, {2, -2}, {2, 0}, {h, 0}, {h, -0.5}, {-h, -0.5}, {-h, 0}, {-2, 0}}, 0));
  auto open = build_coast_model(c, pass_options(0));
  REQUIRE(open.ok());
  std::size_t inside = 0;
  for (const CoastCurve& cc : open->curves)
    for (geo::LonLat p : cc.ll) inside += p.lat < -0.05 && std::abs(p.lon) < 0.1;
  CHECK(inside > 0);
  auto m = build_coast_model(c, pass_options(1500));
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->surfaces.size() == 1);
  CHECK(m->report.count(RepairKind::NarrowWater) >= 1);
  inside = 0;
  for (const CoastCurve& cc : m->curves)
    for (geo::LonLat p : cc.ll) inside += p.lat < -0.045 && std::abs(p.lon) < 0.1;
  CHECK(inside == 0);
}

TEST_CASE("passages: several inlets of one coast are closed, a wider one stays open") {
  // One ring with four dead-end inlets going south from lat 0 at lon -0.6, -0.2, 0.2 and
  // 0.6 (in the box): three narrower than W, the one at 0.2 three times W wide. A round follows the
  // inlets still to close into the loops the first cuts made.
  Coastline c;
  c.file = "comb";
  const double h = kPassW / 2;
  const double centres[4] = {-0.6, -0.2, 0.2, 0.6};
  std::vector<geo::LonLat> corners{{-2, -2}, {2, -2}, {2, 0}};
  for (int k = 3; k >= 0; --k) {
    const double x = centres[k], half = k == 2 ? 3 * h : h;
    for (geo::LonLat p : {geo::LonLat{x + half, 0}, {x + half, -0.5}, {x - half, -0.5}, {x - half, 0}})
      corners.push_back(p);
  }
  corners.push_back({-2, 0});
  c.rings.push_back(pass_ring(corners, 0));
  auto m = build_coast_model(c, pass_options(1500));
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->surfaces.size() == 1);
  CHECK(m->report.count(RepairKind::NarrowWater) >= 3);
  for (int k = 0; k < 4; ++k) {
    std::size_t inside = 0;
    for (const CoastCurve& cc : m->curves)
      for (geo::LonLat p : cc.ll) inside += p.lat < -0.045 && std::abs(p.lon - centres[k]) < 0.1;
    CHECK_MESSAGE((inside > 0) == (k == 2), "inlet at lon ", centres[k]);
  }
}

TEST_CASE("passages: KeepPassages fills the inlets and keeps the canal and the strait open") {
  auto keep = [](double w) {
    ImportOptions o = pass_options(w);
    o.passages.keep_passages = true;
    return o;
  };
  // The canal between two seas: one sea, the canal's coast kept.
  auto canal = build_coast_model(pass_canal(kPassW), keep(1500));
  REQUIRE(canal.ok());
  pass_check_clean(*canal);
  CHECK(canal->surfaces.size() == 1);
  CHECK(canal->report.count(RepairKind::ClosedPassage) == 0);
  CHECK(pass_points_in(*canal, -0.2 + 0.045, 0.2 - 0.045, kPassW / 2 + 1e-9) > 0);
  // Two islands across a narrow strait: still two holes.
  Coastline isl;
  isl.file = "islands";
  isl.rings.push_back(pass_ring({{-0.5, -0.3}, {-kPassW / 2, -0.3}, {-kPassW / 2, 0.3}, {-0.5, 0.3}}, 0));
  isl.rings.push_back(pass_ring({{kPassW / 2, -0.3}, {0.5, -0.3}, {0.5, 0.3}, {kPassW / 2, 0.3}}, 1));
  auto islands = build_coast_model(isl, keep(1500));
  REQUIRE(islands.ok());
  REQUIRE(islands->surfaces.size() == 1);
  CHECK(islands->surfaces[0].holes.size() == 2);
  // A dead-end inlet: filled to its mouth, as without KeepPassages.
  Coastline c;
  c.file = "inlet";
  const double h = kPassW / 2;
  c.rings.push_back(pass_ring({{-2, -2}, {2, -2}, {2, 0}, {h, 0}, {h, -0.5}, {-h, -0.5}, {-h, 0}, {-2, 0}}, 0));
  auto inlet = build_coast_model(c, keep(1500));
  REQUIRE(inlet.ok());
  pass_check_clean(*inlet);
  CHECK(inlet->report.count(RepairKind::NarrowWater) >= 1);
  std::size_t inside = 0;
  for (const CoastCurve& cc : inlet->curves)
    for (geo::LonLat p : cc.ll) inside += p.lat < -0.045 && std::abs(p.lon) < 0.1;
  CHECK(inside == 0);
}

TEST_CASE("passages: a dam by hand across the canal makes two seas; one on land is an error") {
  ImportOptions o = pass_options(0);
  o.passages.dams = {{{0, -0.5}, {0, 0.5}}};
  auto m = build_coast_model(pass_canal(kPassW), o);
  if (!m.ok()) MESSAGE(m.error().to_string());
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->surfaces.size() == 2);
  CHECK(m->report.count(RepairKind::DamPlaced) == 1);
  CHECK(pass_sea_of(*m, {-0.6, 0.5}) != pass_sea_of(*m, {0.6, 0.5}));

  o.passages.dams = {{{0, -0.5}, {0, -0.3}}};   // inside the south wall
  auto bad = build_coast_model(pass_canal(kPassW), o);
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().option == "Dams");
  CHECK(bad.error().message.find("crosses no water") != std::string::npos);
}

TEST_CASE("passages: SeaAt keeps the sea holding the point; a point on land names its ring") {
  ImportOptions o = pass_options(1500);
  o.sea_at = {{-0.6, 0.5}};
  auto m = build_coast_model(pass_canal(kPassW), o);
  REQUIRE(m.ok());
  CHECK(m->surfaces.size() == 1);
  CHECK(m->seas_dropped == 1);
  CHECK(pass_sea_of(*m, {-0.6, 0.5}) == 0);
  CHECK(pass_sea_of(*m, {0.6, 0.5}) == -1);

  o.sea_at = {{0, 0.5}};   // in the north wall (record 1)
  auto bad = build_coast_model(pass_canal(kPassW), o);
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().option == "SeaAt");
  CHECK(bad.error().message.find("record 1") != std::string::npos);
}

TEST_CASE("passages: KeepOpen keeps the canal open whatever MinChannelWidth, reported with its width") {
  ImportOptions o = pass_options(1500);
  o.passages.keep_open = {{0.1, 0}};   // in the canal, off its middle
  auto m = build_coast_model(pass_canal(kPassW), o);
  if (!m.ok()) MESSAGE(m.error().to_string());
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->surfaces.size() == 1);
  CHECK(m->report.count(RepairKind::ClosedPassage) == 0);
  CHECK(pass_points_in(*m, -0.15, 0.15, kPassW / 2 + 1e-9) > 0);
  REQUIRE(m->report.count(RepairKind::KeptOpen) == 1);
  for (const RepairEntry& e : m->report.repair)
    if (e.kind == RepairKind::KeptOpen) {
      CHECK(e.where.lon == 0.1);
      CHECK(e.value == doctest::Approx(1112).epsilon(0.01));
    }
}

TEST_CASE("passages: KeepOpen keeps a strait between two islands open; the one elsewhere still merges") {
  Coastline c;
  c.file = "islands";
  c.rings.push_back(pass_ring({{-0.5, -0.3}, {-kPassW / 2, -0.3}, {-kPassW / 2, 0.3}, {-0.5, 0.3}}, 0));
  c.rings.push_back(pass_ring({{kPassW / 2, -0.3}, {0.5, -0.3}, {0.5, 0.3}, {kPassW / 2, 0.3}}, 1));
  ImportOptions o = pass_options(1500);
  o.passages.keep_open = {{0, 0.2}};
  auto m = build_coast_model(c, o);
  REQUIRE(m.ok());
  pass_check_clean(*m);
  REQUIRE(m->surfaces.size() == 1);
  CHECK(m->surfaces[0].holes.size() == 2);
  CHECK(m->report.count(RepairKind::ClosedPassage) == 0);
  CHECK(m->report.count(RepairKind::KeptOpen) == 1);
}

TEST_CASE("passages: a KeepOpen point on land, or with a dam across its passage, is an error") {
  ImportOptions o = pass_options(1500);
  o.passages.keep_open = {{0, 0.5}};   // in the north wall
  auto land = build_coast_model(pass_canal(kPassW), o);
  REQUIRE_FALSE(land.ok());
  CHECK(land.error().option == "KeepOpen");
  CHECK(land.error().message.find("lies on land") != std::string::npos);

  o.passages.keep_open = {{0, 0}};
  o.passages.dams = {{{0.05, -0.5}, {0.05, 0.5}}};   // across the canal near the point
  auto dam = build_coast_model(pass_canal(kPassW), o);
  REQUIRE_FALSE(dam.ok());
  CHECK(dam.error().option == "KeepOpen");
  CHECK(dam.error().message.find("dam from") != std::string::npos);
}

TEST_CASE("passages: each sea SeaAt drops is reported with a point inside it and its area") {
  ImportOptions o = pass_options(1500);
  o.sea_at = {{-0.6, 0.5}};
  auto m = build_coast_model(pass_canal(kPassW), o);
  REQUIRE(m.ok());
  REQUIRE(m->report.count(RepairKind::DroppedSea) == 1);
  for (const RepairEntry& e : m->report.repair)
    if (e.kind == RepairKind::DroppedSea) {
      // The east sea: lon 0.2 .. 1, lat -1 .. 1 (0.8 x 2 degrees of 111.2 km).
      CHECK(e.where.lon > 0.2);
      CHECK(e.where.lon < 1);
      CHECK(std::abs(e.where.lat) < 1);
      CHECK(e.value == doctest::Approx(0.8 * 2 * 111.19 * 111.19).epsilon(0.01));
    }
  const auto items = m->report.items();
  bool ranked = false;
  for (const ReportLine& l : items) ranked = ranked || (l.sea_dropped && l.rank == m->report.repair.back().value);
  CHECK(ranked);
}

TEST_CASE("passages: a 30 m pinch between long coarse segments is closed (KeepPassages = 0)") {
  // Two islands 30 m apart at lat 0, where a spike of one faces the straight side of the
  // other, the source dense (a point every ~55 m) and gamma 2 km, so the coarse segments at
  // the pinch are long. The code before the refused-cut refinement closed this one too; the
  // case it left open, the Cymyran Strait, is tests/scripts/coastline/holy_island_strait.geo.
  // This guards that putting original points back leaves such a closure clean.
  auto side = [](double sign) {
    std::vector<geo::LonLat> r;
    const double tip = sign * 0.000135;   // 15 m from lon 0
    if (sign < 0) {   // a straight side against the other's point
      pass_line(r, {-0.5, -0.3}, {tip, -0.3}, 0.0005);
      pass_line(r, {tip, -0.3}, {tip, 0.3}, 0.0005);
      pass_line(r, {tip, 0.3}, {-0.5, 0.3}, 0.0005);
      pass_line(r, {-0.5, 0.3}, {-0.5, -0.3}, 0.0005);
    } else {
      pass_line(r, {0.5, -0.3}, {0.5, 0.3}, 0.0005);
      pass_line(r, {0.5, 0.3}, {0.05, 0.3}, 0.0005);
      pass_line(r, {0.05, 0.3}, {0.05, 0.01}, 0.0005);
      pass_line(r, {0.05, 0.01}, {tip, 0}, 0.0005);   // a spike 5.5 km long, 2.2 km wide at its root
      pass_line(r, {tip, 0}, {0.05, -0.01}, 0.0005);
      pass_line(r, {0.05, -0.01}, {0.05, -0.3}, 0.0005);
      pass_line(r, {0.05, -0.3}, {0.5, -0.3}, 0.0005);
    }
    return r;
  };
  Coastline c;
  c.file = "pinch";
  for (int i = 0; i < 2; ++i) {
    Ring r;
    r.pts = side(i == 0 ? -1.0 : 1.0);
    r.id = i;
    r.record = static_cast<std::size_t>(i);
    c.rings.push_back(std::move(r));
  }
  ImportOptions o = pass_options(2000);
  o.gamma = testing::constant_accuracy(2000);
  auto m = build_coast_model(c, o);
  if (!m.ok()) MESSAGE(m.error().to_string());
  REQUIRE(m.ok());
  pass_check_clean(*m);
  REQUIRE(m->surfaces.size() == 1);
  CHECK(m->surfaces[0].holes.size() == 1);   // the islands joined
  // The spike is land up to where the water beside it is wider than W: no point of it
  // within 0.01 degrees (1.1 km) of its tip, where the water is narrower than 600 m.
  CHECK(pass_points_in(*m, 0, 0.01, 0.01) == 0);
}

namespace {

// A sea (lon -1..1, lat 0..north, counter-clockwise: water on the left) whose south coast has
// a dead-end inlet 0.2 degrees deep at each of `centres`: the one at `wide` three times
// kPassW wide, the others kPassW. Points every 0.0005 degrees, every 20th kept (and the
// corners), so that the loop has 20 times more points than its polygon.
std::pair<std::vector<WorkCurve>, std::vector<WorkLoop>> comb_loop(const std::vector<double>& centres, double wide,
                                                                    double north = 0.5) {
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  WorkCurve c;
  c.periodic = true;
  auto line = [&](geo::LonLat a, geo::LonLat b) {
    const int n = std::max(1, static_cast<int>(std::lround(std::hypot(b.lon - a.lon, b.lat - a.lat) / 0.0005)));
    for (int i = 0; i < n; ++i) {
      if (i % 20 == 0) c.keep.push_back(static_cast<std::uint32_t>(c.full.size()));
      const geo::LonLat p{a.lon + (b.lon - a.lon) * i / n, a.lat + (b.lat - a.lat) * i / n};
      c.full.push_back(p);
      c.uv.push_back(ps.param_from_lonlat(p));
      c.gamma.push_back(300);
    }
  };
  std::vector<geo::LonLat> corners{{-1, 0}};
  for (double x : centres) {
    const double half = x == wide ? 1.5 * kPassW : kPassW / 2;
    for (geo::LonLat p : {geo::LonLat{x - half, 0}, {x - half, -0.2}, {x + half, -0.2}, {x + half, 0}})
      corners.push_back(p);
  }
  for (geo::LonLat p : {geo::LonLat{1, 0}, {1, north}, {-1, north}}) corners.push_back(p);
  for (std::size_t i = 0; i < corners.size(); ++i) line(corners[i], corners[(i + 1) % corners.size()]);
  WorkLoop l;
  l.curves = {0};
  l.hole = false;
  return {{std::move(c)}, {std::move(l)}};
}

struct CombRun {
  std::vector<std::tuple<int, double, double, double>> closures;   // kind, lon, lat, value
  PassageStats stats;
  std::size_t points = 0;   // the loop's points before
  std::size_t left_in_narrow = 0, left_in_wide = 0;   // points below lat -0.025 in the inlets after
};

CombRun comb_run(const std::vector<double>& centres, double wide, double north = 0.5) {
  auto [curves, loops] = comb_loop(centres, wide, north);
  CombRun r;
  r.points = curves[0].full.size();
  PassageOptions o;
  o.min_width = 1500;
  o.keep_passages = true;
  std::vector<RepairEntry> log;
  auto changed = close_passages(curves, loops, o, log, &r.stats);
  REQUIRE(changed.ok());
  for (const RepairEntry& e : log)
    r.closures.emplace_back(static_cast<int>(e.kind), e.where.lon, e.where.lat, e.value);
  std::sort(r.closures.begin(), r.closures.end());
  for (const WorkLoop& l : loops) {
    if (l.dead) continue;
    for (std::uint32_t ci : l.curves)
      for (geo::LonLat p : curves[ci].full)
        if (p.lat < -0.025) (std::abs(p.lon - wide) < 0.02 ? r.left_in_wide : r.left_in_narrow) += 1;
  }
  return r;
}

}  // namespace

TEST_CASE("passages: closing many inlets of one loop reads each of its points a bounded number of times") {
  // Forty inlets on one loop of 64,000 points: copying the loop at each cut or dead-end test
  // (as close_passages once did) reads it once per inlet, 40 times its size and more.
  std::vector<double> centres;
  for (int k = 0; k < 40; ++k) centres.push_back(-0.78 + 0.04 * k);
  const double wide = centres[17];
  const CombRun all = comb_run(centres, wide);
  // Filled up to a stub at the mouth no longer than its width (two kept segments deep):
  // its two sides are the sides of one corner, not a passage.
  CHECK(all.left_in_narrow == 0);
  CHECK(all.left_in_wide > 0);
  CHECK(all.stats.cuts >= 39);
  // Flattening reads every point once and the rebuild twice (first to know which curves
  // each ring reads, so that each is freed after its last reader); cuts read none.
  CHECK(all.stats.node_visits <= 4 * all.points);
  // The reference: each inlet alone on the same coast. Closing is local, so the closures
  // (places and widths) of the forty together are those of the forty alone.
  std::vector<std::tuple<int, double, double, double>> reference;
  for (double x : centres) {
    const CombRun one = comb_run({x}, wide);
    reference.insert(reference.end(), one.closures.begin(), one.closures.end());
  }
  std::sort(reference.begin(), reference.end());
  CHECK(all.closures.size() == reference.size());
  CHECK(all.closures == reference);
  // Every piece a cut drops or would drop, and the sea after each cut, ask their mean
  // width; the rope's sums decide (coast/mean_width.h), and the pass round the ring is
  // made only for the narrow water logged with its width (a near tie would add one).
  std::size_t narrow = 0;
  for (const auto& c : all.closures) narrow += std::get<0>(c) == static_cast<int>(RepairKind::NarrowWater);
  MESSAGE("mean widths asked ", all.stats.width_tests, ", read round the ring ", all.stats.width_passes,
          ", narrow water logged ", narrow);
  CHECK(all.stats.width_tests >= 2 * all.stats.cuts);
  CHECK(all.stats.width_passes == narrow);
}

TEST_CASE("passages: a cut's work on the kept points does not grow with the loop's size") {
  // The forty inlets of the test above, on a sea 1 and 40 degrees deep: 44,000 and 200,000
  // points, 2,200 and 10,000 kept. Each cut and dead-end test once copied the loop's kept
  // points (three times its size per cut); the ropes' work per cut grows with log n only.
  std::vector<double> centres;
  for (int k = 0; k < 40; ++k) centres.push_back(-0.78 + 0.04 * k);
  const CombRun shallow = comb_run(centres, centres[17], 1.0), deep = comb_run(centres, centres[17], 40.0);
  REQUIRE(shallow.stats.cuts >= 39);
  CHECK(deep.closures == shallow.closures);
  const double per_cut_shallow =
      static_cast<double>(shallow.stats.kept_visits) / static_cast<double>(shallow.stats.cuts);
  const double per_cut_deep = static_cast<double>(deep.stats.kept_visits) / static_cast<double>(deep.stats.cuts);
  MESSAGE("kept points visited per cut: ", per_cut_shallow, " at ", shallow.points, " points, ", per_cut_deep, " at ",
          deep.points);
  CHECK(per_cut_deep < 1.5 * per_cut_shallow);
  // The sea's mean width after each cut comes from the rope's sums, whatever its size.
  CHECK(deep.stats.width_passes == shallow.stats.width_passes);
}

namespace {

// The mouth of a lagoon behind a spit whose tip lies over the far bank, as GSHHG
// intermediate has it at Sontecomapan (95.0W 18.56N; examples/gulf_of_mexico.geo at 5 km,
// once the deviation bound put the points back): the points moved by (+95, -18.56)
// degrees, the spit's sea side running west to the box and the far bank east, the land
// closed round the south. The narrowest clean cut joins the spit's tip to the far bank's
// point under the spit's inner side: its dam runs west-south-west and the bank leaves that
// point east-north-east, a corner of 1.8 degrees of sea (the mesh there had rho 0.14).
Coastline spit_lagoon() {
  Coastline c;
  c.file = "lagoon";
  Ring r;
  r.pts = {{-0.041733, 0.023276}, {0.012741, 0.001608},    // the spit's sea side, its tip
           {-0.008469, -0.000146}, {-0.030976, -0.025248}, {-0.024338, -0.047449},
           {0.011521, -0.031809},  {0.0, -0.012964},       // the lagoon
           {-0.006790, -0.001825}, {0.0, -0.000757},       // the far bank's point at the mouth
           {0.026703, 0.003363}};                         // the far bank going east
  std::vector<geo::LonLat> rest;
  pass_line(rest, {0.026703, 0.003363}, {2, 0.003363});
  pass_line(rest, {2, 0.003363}, {2, -2});
  pass_line(rest, {2, -2}, {-2, -2});
  pass_line(rest, {-2, -2}, {-2, 0.023276});
  pass_line(rest, {-2, 0.023276}, {-0.041733, 0.023276});
  r.pts.insert(r.pts.end(), rest.begin() + 1, rest.end());   // from the far bank's next point
  r.id = 0;
  r.record = 0;
  c.rings.push_back(std::move(r));
  return c;
}

// The sea's angle (degrees) at every point where one curve of a loop meets the next (a
// dam's ends among them): the angle from the next curve's first control segment round to
// the previous curve's last one, water on the left.
std::vector<std::pair<double, geo::LonLat>> junction_angles(const CoastModel& m) {
  std::vector<std::pair<double, geo::LonLat>> out;
  for (const CoastLoop& loop : m.loops) {
    if (loop.curves.size() < 2) continue;
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const CoastCurve& in = m.curves[loop.curves[k]];
      const CoastCurve& next = m.curves[loop.curves[(k + 1) % loop.curves.size()]];
      const Vec2 v = next.uv.front(), u = in.uv[in.uv.size() - 2], x = next.uv[1];
      const Vec2 o = x - v, i = u - v;
      double a = std::atan2(o.x * i.y - o.y * i.x, dot(o, i));
      if (a < 0) a += 2 * geo::kPi;
      out.push_back({a * 180 / geo::kPi, next.ll.front()});
    }
  }
  return out;
}

}  // namespace

TEST_CASE("passages: a dam at a lagoon's mouth makes no corner sharper than the mesh can follow") {
  const Coastline c = spit_lagoon();
  ImportOptions o = pass_options(2000);
  o.gamma = testing::constant_accuracy(300);   // every point kept, as the bound left them
  o.deviation.factor = 0;                      // and no more: the passages see these points
  auto m = build_coast_model(c, o);
  if (!m.ok()) MESSAGE(m.error().to_string());
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->report.count(RepairKind::NarrowWater) >= 1);   // the lagoon filled
  CHECK(pass_points_in_box(*m, -0.04, 0.02, -0.05, -0.01) == 0);   // no point left in the lagoon
  // Every corner of the sea where a dam meets the coast: at least 15 degrees (the floor's
  // rho 0.3 needs 9.4); before, 1.8 degrees at the far bank's point (0, -0.000757).
  std::size_t dams = 0;
  for (const auto& [angle, at] : junction_angles(*m)) {
    ++dams;
    INFO("corner at lon " << at.lon << " lat " << at.lat);
    CHECK(angle >= 15);
  }
  CHECK(dams >= 2);
}

TEST_CASE("passages: a closing round keeps the polygons and near pairs of what did not change") {
  // The sea of comb_loop with one narrow inlet, and two islands in it across a strait
  // narrower than the width (kept open: KeepPassages = 1). The first round measures the
  // three loops and searches every segment; it fills the inlet, which makes a new sea
  // loop. The next round measures that loop alone, takes the islands' polygons from the
  // round before, searches only the segments the cut made (the dam) and takes the
  // strait's near pairs as they were.
  auto [curves, loops] = comb_loop({0.3}, -0.5);
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  std::size_t segments = curves[0].keep.size();
  auto island = [&](double lon0, double lon1) {   // clockwise: water on the left
    WorkCurve c;
    c.periodic = true;
    for (geo::LonLat p : {geo::LonLat{lon0, 0.3}, {lon0, 0.4}, {lon1, 0.4}, {lon1, 0.3}}) {   // each side one segment
      c.keep.push_back(static_cast<std::uint32_t>(c.full.size()));
      c.full.push_back(p);
      c.uv.push_back(ps.param_from_lonlat(p));
      c.gamma.push_back(300);
    }
    segments += c.keep.size();
    WorkLoop l;
    l.curves = {static_cast<std::uint32_t>(curves.size())};
    l.hole = true;
    curves.push_back(std::move(c));
    loops.push_back(std::move(l));
  };
  island(-0.2, -0.1);
  island(-0.1 + kPassW, 0.0);
  PassageOptions o;
  o.min_width = 1500;
  o.keep_passages = true;
  std::vector<RepairEntry> log;
  PassageStats stats;
  auto changed = close_passages(curves, loops, o, log, &stats);
  REQUIRE(changed.ok());
  CHECK(*changed);
  CHECK(stats.cuts >= 1);
  // Made: the three loops, then the new sea; kept: the two islands in every later round.
  CHECK(stats.polygons_made >= 4);
  CHECK(stats.polygons_kept >= 2);
  CHECK(stats.polygons_kept % 2 == 0);
  // Every segment once, then only the few a cut made.
  CHECK(stats.near_searched >= segments);
  CHECK(stats.near_searched < segments + 10);
  // The strait's pair (facing sides of the two islands) taken from the round before.
  CHECK(stats.near_kept >= 1);
  // The sea's own near pairs that outlive the cut keep their ways across: each measured
  // once, in the first round that asks.
  MESSAGE("near pairs kept " << stats.near_kept << ", ways across kept " << stats.across_kept);
  CHECK(stats.across_kept >= 1);
  // The strait is kept open: both islands live on, unchanged.
  std::size_t islands = 0;
  for (std::size_t l = 1; l < 3; ++l) islands += !loops[l].dead;
  CHECK(islands == 2);
}

namespace {

// A river mouth behind a spit as the full GSHHG has it near 105.81E 19.61N (Gulf of Tonkin,
// the World Ocean at 3 km), its kept points after coarsening at 3 km: the points moved by
// (-105.81, -19.61) degrees, longitudes scaled by cos 19.61 degrees (the same shape at the
// equator), the coast running north with the land to the west and closed round it. From
// the south: the coast up to the mouth's south bank (point 3), the river's channel (4, 5,
// 6), the spit's inner side (7, its tip 8 lying 90 m east of point 3's bank) and its sea
// side on north. The narrowest clean cut (1702 m) joins the spit's inner corner 7 to the
// bank's point 3: its dam runs back along the spit's inner side, a corner of 2 degrees of
// sea at 7; the cuts next to it are not clean, and the one the rule moved it to (6 to 3)
// made a corner of 65 degrees on the control polygon but 0.5 on the B-spline, which cuts
// the spike at 7 off (the mesh's worst triangle of the world, rho 0.0006).
Coastline river_mouth_behind_spit() {
  Coastline c;
  c.file = "river mouth";
  const std::vector<geo::LonLat> mouth = {
      {0.001969, -0.085000}, {0.005887, -0.057530}, {0.008666, -0.030420}, {0.008186, -0.002520},   // 0-3
      {-0.013000, -0.020030}, {-0.025538, -0.005000}, {-0.005916, 0.006660},                         // 4-6
      {0.003919, 0.012890},  {0.012934, -0.014200},                                                 // 7, 8
      {0.020046, 0.014980},  {0.026329, 0.041640},  {0.035683, 0.067470}, {0.047439, 0.092480}};    // 9-12
  Ring r;
  pass_line(r.pts, {0.001969, -2}, mouth.front());
  r.pts.insert(r.pts.end(), mouth.begin(), mouth.end() - 1);
  pass_line(r.pts, mouth.back(), {0.047439, 2});
  pass_line(r.pts, {0.047439, 2}, {-2, 2});
  pass_line(r.pts, {-2, 2}, {-2, -2});
  pass_line(r.pts, {-2, -2}, {0.001969, -2});
  r.id = 0;
  r.record = 0;
  c.rings.push_back(std::move(r));
  return c;
}

// The sea's angle (degrees) where one curve of a loop meets the next, as a mesh of edge
// `h` metres sees it: between the chords from the junction to the points of the two
// curves as drawn (the uniform cubic B-spline, geo/curve_bspline.h) at arc length h along
// each (or its far end when it is shorter). The smallest over h in `sizes`.
std::vector<std::pair<double, geo::LonLat>> drawn_junction_angles(const CoastModel& m, std::vector<double> sizes) {
  // The curve's points at arc lengths `sizes` from its start (forward) or its end.
  auto at_lengths = [&](const CoastCurve& c, bool from_end) {
    constexpr int kSamples = 4000;
    std::vector<Vec2> line;
    for (int i = 0; i <= kSamples; ++i) {
      const double t = static_cast<double>(i) / kSamples;
      line.push_back(geo::eval_bspline_uniform(std::span<const Vec2>(c.uv), false, from_end ? 1 - t : t).p);
    }
    std::vector<Vec2> out;
    for (double h : sizes) {
      double run = 0;
      Vec2 q = line.back();
      for (std::size_t i = 1; i < line.size(); ++i) {
        const Vec2 mid = 0.5 * (line[i] + line[i - 1]);
        run += norm(line[i] - line[i - 1]) * 2 * geo::kEarthRadius / (1 + norm2(mid));
        if (run >= h) {
          q = line[i];
          break;
        }
      }
      out.push_back(q);
    }
    return out;
  };
  std::vector<std::pair<double, geo::LonLat>> out;
  for (const CoastLoop& loop : m.loops) {
    if (loop.curves.size() < 2) continue;
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const CoastCurve& in = m.curves[loop.curves[k]];
      const CoastCurve& next = m.curves[loop.curves[(k + 1) % loop.curves.size()]];
      const Vec2 v = next.uv.front();
      const auto ins = at_lengths(in, true), outs = at_lengths(next, false);
      double sharpest = 360;
      for (std::size_t s = 0; s < sizes.size(); ++s) {
        const Vec2 o = outs[s] - v, i = ins[s] - v;
        double a = std::atan2(o.x * i.y - o.y * i.x, dot(o, i));
        if (a < 0) a += 2 * geo::kPi;
        sharpest = std::min(sharpest, a * 180 / geo::kPi);
      }
      out.push_back({sharpest, next.ll.front()});
    }
  }
  return out;
}

}  // namespace

TEST_CASE("passages: a dam at a river mouth behind a spit makes no corner the mesh cannot fill, as drawn") {
  const Coastline c = river_mouth_behind_spit();
  ImportOptions o = pass_options(3000);          // MinChannelWidth 3 km, as the World Ocean at 3 km
  o.passages.keep_passages = true;
  o.gamma = testing::constant_accuracy(300);     // every point kept, as the coarsening left them
  o.deviation.factor = 0;
  auto m = build_coast_model(c, o);
  if (!m.ok()) MESSAGE(m.error().to_string());
  REQUIRE(m.ok());
  pass_check_clean(*m);
  CHECK(m->report.count(RepairKind::NarrowWater) >= 1);   // the river filled
  // The river's channel is land now: no curve point inside it.
  CHECK(pass_points_in_box(*m, -0.024, -0.007, -0.015, 0.004) == 0);
  // Every junction of the sea's loop at the mesh sizes up to 3 km: at least 9.4 degrees, the
  // angle Mesh.QualityFloor 0.3 needs (mesh/quality_floor.h); before, 2.5 degrees at point 6
  // (0.5 between the World Ocean's mesh edges there).
  std::size_t junctions = 0;
  for (const auto& [angle, at] : drawn_junction_angles(*m, {500, 1000, 1500, 2000, 2500, 3000})) {
    ++junctions;
    INFO("corner at lon " << at.lon << " lat " << at.lat << ": " << angle << " degrees");
    CHECK(angle >= 9.4);
  }
  CHECK(junctions >= 2);
}

TEST_CASE("passages: the same closures on 1, 2 and 3 threads on real data (loops flattened in chunks)") {
  // Great Britain and Ireland at full resolution: many loops, so the pool's nodes are
  // numbered in many chunks of loops; the rounds order segments by node, so nodes numbered
  // in the order the chunks finish would change which passages close first.
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(c.ok());
  auto model = [&](int threads) {
    ImportOptions o;
    o.gamma = testing::constant_accuracy(1500);
    o.passages.min_width = 1500;
    o.threads = threads;
    auto m = build_coast_model(*c, o);
    REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
    return std::move(*m);
  };
  const CoastModel one = model(1);
  REQUIRE(one.loops.size() > 4 * 16);   // flatten_loops takes 16 loops a chunk
  REQUIRE(one.report.count(RepairKind::ClosedPassage) + one.report.count(RepairKind::NarrowWater) > 10);
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    const CoastModel m = model(threads);
    REQUIRE(m.curves.size() == one.curves.size());
    for (std::size_t i = 0; i < m.curves.size(); ++i) {
      REQUIRE(m.curves[i].uv.size() == one.curves[i].uv.size());
      CHECK(std::equal(m.curves[i].uv.begin(), m.curves[i].uv.end(), one.curves[i].uv.begin()));
    }
    REQUIRE(m.loops.size() == one.loops.size());
    for (std::size_t l = 0; l < m.loops.size(); ++l) CHECK(m.loops[l].curves == one.loops[l].curves);
    REQUIRE(m.report.repair.size() == one.report.repair.size());
    for (std::size_t i = 0; i < m.report.repair.size(); ++i) {
      CHECK(m.report.repair[i].kind == one.report.repair[i].kind);
      CHECK(m.report.repair[i].where.lon == one.report.repair[i].where.lon);
      CHECK(m.report.repair[i].where.lat == one.report.repair[i].where.lat);
      CHECK(m.report.repair[i].value == one.report.repair[i].value);
    }
  }
}
