// The whole import pipeline on real data: topology and orientation on the PolarSphere,
// consistency (no intersections left), regions, and the paper's Figure 5 table.
#include "coast/import.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/intersections.h"
#include "exact/ring.h"
#include "coast/read_gshhs.h"
#include "coast/read_lonlat_text.h"
#include "coast/read_shapefile.h"
#include "coast/constant_accuracy.h"
#include "coast/loop_uv.h"

using namespace sm;
using namespace sm::coast;

namespace {

Coastline load(const char* name) {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/" + name);
  REQUIRE(c.ok());
  return std::move(*c);
}

// Invariants every model must satisfy.
void check_model(const CoastModel& m) {
  std::vector<std::vector<Vec2>> polys;
  for (std::uint32_t l = 0; l < m.loops.size(); ++l) polys.push_back(testing::loop_uv(m, l));
  CHECK(find_intersections(polys).empty());
  for (const CoastSurface& s : m.surfaces) {
    CHECK(ring_orientation(polys[s.outer]) == Sign::Positive);
    for (std::uint32_t h : s.holes) {
      CHECK(ring_orientation(polys[h]) == Sign::Negative);
      CHECK(point_in_ring(polys[s.outer], polys[h][0]));
    }
  }
  for (const CoastLoop& loop : m.loops) {
    for (std::size_t i = 0; loop.curves.size() > 1 && i < loop.curves.size(); ++i) {
      const auto& a = m.curves[loop.curves[i]];
      const auto& b = m.curves[loop.curves[(i + 1) % loop.curves.size()]];
      CHECK(a.uv.back() == b.uv.front());
      CHECK_FALSE(a.periodic);
    }
  }
  for (const CoastCurve& c : m.curves) {
    REQUIRE(c.uv.size() == c.ll.size());
    if (c.periodic) CHECK(c.uv.size() >= 3);
    const geo::PolarSphere ps({0, 0, 0}, 1.0);
    for (std::size_t k = 0; k < c.uv.size(); k += 7) {
      const Vec2 uv = ps.param_from_lonlat(c.ll[k]);
      CHECK(uv.x == doctest::Approx(c.uv[k].x));
      CHECK(uv.y == doctest::Approx(c.uv[k].y));
    }
  }
}
}  // namespace

TEST_CASE("import: the world ocean at 100 km is bounded by Antarctica") {
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(100e3);
  auto m = build_coast_model(load("world_c.txt"), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  REQUIRE(m->surfaces.size() == 1);
  const CoastSurface& ocean = m->surfaces[0];
  CHECK(ocean.outer == 0);
  const CoastCurve& outer = m->curves[m->loops[ocean.outer].curves[0]];
  CHECK(outer.periodic);
  for (auto p : outer.ll) CHECK(p.lat < -60);   // Antarctica
  CHECK(ocean.holes.size() > 50);
  CHECK(m->unassigned.empty());
  check_model(*m);
}

TEST_CASE("import: the original GSHHS crude binary (levels 1 + Antarctic ice front)") {
  auto c = read_gshhs(std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b");
  REQUIRE(c.ok());
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(50e3);
  auto m = build_coast_model(std::move(*c), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  REQUIRE(m->surfaces.size() == 1);
  for (auto p : m->curves[m->loops[m->surfaces[0].outer].curves[0]].ll) CHECK(p.lat < -60);
  check_model(*m);
  ImportOptions no_ant = o;
  no_ant.antarctica_level = 0;
  auto c2 = read_gshhs(std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b");
  auto m2 = build_coast_model(std::move(*c2), no_ant);
  REQUIRE(m2.ok());
  CHECK(m2->surfaces.empty());          // no loop round the singular point: no outer boundary
  CHECK(m2->unassigned.size() > 100);
}

TEST_CASE("import: world intermediate at 10 km: crossings made by coarsening are repaired") {
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(10e3);
  auto m = build_coast_model(load("world_i_A100.txt"), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  CHECK(m->report.count(RepairKind::Refined) > 0);
  // One line per repair (each with its place and figure) after the summaries.
  const auto items = m->report.items();
  REQUIRE(items.size() > m->report.repair.size());
  const std::size_t summaries = items.size() - m->report.repair.size();
  for (std::size_t i = 0; i < m->report.repair.size(); ++i) {
    const ReportLine& l = items[summaries + i];
    CHECK(l.has_place);
    CHECK(l.where.lon == m->report.repair[i].where.lon);
    CHECK_FALSE(l.what.empty());
    CHECK(l.text.find(l.what) != std::string::npos);
    if (m->report.repair[i].kind == RepairKind::Refined) CHECK(l.figure.find(" point") != std::string::npos);
  }
  check_model(*m);
}

TEST_CASE("import: regions make open-boundary curves") {
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(1500);
  auto m = build_coast_model(load("gb_ireland_f.txt"), o);   // the file's own box closes the French coast
  REQUIRE(m.ok());
  std::size_t open = 0;
  for (const auto& c : m->curves) open += c.open_boundary;
  CHECK(open == 2);
  check_model(*m);
  ImportOptions r = o;
  r.gamma = sm::testing::constant_accuracy(5000);
  r.region = LonLatBox{-4, 9, 50, 58};
  auto ns = build_coast_model(load("northsea_scheldt_f.txt"), r);
  REQUIRE_MESSAGE(ns.ok(), (ns.ok() ? "" : ns.error().to_string()));
  open = 0;
  for (const auto& c : ns->curves) open += c.open_boundary;
  CHECK(open >= 2);
  check_model(*ns);
  ImportOptions none = o;
  none.use_file_region = false;
  CHECK_FALSE(build_coast_model(load("gb_ireland_f.txt"), none).ok());
}

TEST_CASE("import: MinArea drops small islands") {
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(150);
  o.coarsen.min_area_km2 = 10;
  auto m = build_coast_model(load("gb_ireland_f.txt"), o);
  REQUIRE(m.ok());
  CHECK(m->surfaces[0].holes.size() < 200);
  std::size_t small = 0;
  for (const auto& d : m->report.dropped) small += d.reason == DropReason::BelowMinArea;
  CHECK(small > 2000);
}

// Figure 5 of the paper (GSHHS 2008 full resolution): gamma = 100 km: GB and Ireland only;
// 15 km: "15 contours"; 1.5 km: 152 islands; 150 m: 2,176 islands, 83,277 control points.
// Ours (GSHHG 2.3.7 full, gb_ireland_f.txt): 2, 16, 155, 2438 islands and 81,848 island
// control points (docs/coastlines.md discusses the differences).
TEST_CASE("import: Figure 5, Great Britain and Ireland") {
  struct Row { double gamma; std::size_t paper, lo, hi; };
  const Row rows[] = {{100e3, 2, 2, 2}, {15e3, 15, 13, 18}, {1.5e3, 152, 140, 165}, {150, 2176, 2176, 2600}};
  for (const Row& r : rows) {
    CAPTURE(r.gamma);
    ImportOptions o;
    o.gamma = sm::testing::constant_accuracy(r.gamma);
    o.deviation.factor = 0;   // the paper's control points: coarsening alone, no point put back
    auto m = build_coast_model(load("gb_ireland_f.txt"), o);
    REQUIRE(m.ok());
    REQUIRE(m->surfaces.size() == 1);
    const std::size_t islands = m->surfaces[0].holes.size();
    CHECK(islands >= r.lo);
    CHECK(islands <= r.hi);
    if (r.gamma == 150) {
      std::size_t pts = 0;
      for (std::uint32_t h : m->surfaces[0].holes) pts += m->curves[m->loops[h].curves[0]].uv.size();
      CHECK(pts == doctest::Approx(83277).epsilon(0.05));
    }
    check_model(*m);
  }
}

TEST_CASE("import: Natural Earth land (dateline splits merged, Antarctica closed at the pole)") {
  auto c = read_shapefile(std::string(SM_DATA_DIR) + "/naturalearth/ne_110m_land.shp");
  REQUIRE(c.ok());
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(20e3);
  auto m = build_coast_model(std::move(*c), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  REQUIRE(m->surfaces.size() == 1);
  for (auto p : m->curves[m->loops[m->surfaces[0].outer].curves[0]].ll) CHECK(p.lat < -60);
  CHECK(m->report.clean.count(CleanAction::MergedRings) == 3);
  check_model(*m);
}

TEST_CASE("import: an islet overlapping the mainland in GSHHG high becomes part of it") {
  // canadian_arctic_h.txt record 3255 (6 points, 107.68W 68.20N) crosses the cut mainland
  // coast (record 13145) in the source itself; at 200 m both survive the coarsening.
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(200);
  auto m = build_coast_model(load("canadian_arctic_h.txt"), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  bool found = false;
  for (const auto& e : m->report.repair)
    if (e.kind == RepairKind::UnitedIslands && e.record == 3255) {
      found = true;
      CHECK(e.where.lon == doctest::Approx(-107.68).epsilon(1e-3));
      CHECK(e.where.lat == doctest::Approx(68.20).epsilon(1e-3));
    }
  CHECK(found);
  check_model(*m);
}

TEST_CASE("import: a region across the dateline with a variable accuracy field") {
  // Bering Strait box written past 180, gamma 5 km near (190E, 66N) growing to 50 km.
  ImportOptions o;
  const Vec3 centre = geo::sphere_from_lonlat({190, 66}, geo::kEarthRadius);
  o.gamma = [centre](std::span<const Vec3> pts, std::span<double> g) {
    for (std::size_t i = 0; i < pts.size(); ++i) g[i] = std::min(50e3, 5e3 + 0.05 * norm(pts[i] - centre));
  };
  o.region = LonLatBox{170, 200, 60, 72};
  auto m = build_coast_model(load("world_l.txt"), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  std::size_t open = 0, coast = 0;
  for (const auto& c : m->curves) {
    (c.open_boundary ? open : coast)++;
    for (auto p : c.ll) {
      const double lon = std::fmod(p.lon + 720.0, 360.0);
      CHECK((lon >= 170 - 1e-9 || lon <= 200 - 360 + 1e-9));
      CHECK(p.lat >= 60 - 1e-9);
      CHECK(p.lat <= 72 + 1e-9);
    }
  }
  CHECK(open >= 2);   // Siberia and Alaska are both cut by the box
  CHECK(coast >= 2);
  check_model(*m);
  // Points are denser near the strait than far from it.
  std::size_t near = 0, far = 0;
  for (const auto& c : m->curves)
    if (!c.open_boundary)
      for (auto p : c.ll) (norm(geo::sphere_from_lonlat(p, geo::kEarthRadius) - centre) < 300e3 ? near : far)++;
  CHECK(near > 0);
  CHECK(far > 0);
}

TEST_CASE("import: Antarctica's grounding line (level 6) absorbs the ice-shelf islands it crosses") {
  auto c = read_gshhs(std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b");
  REQUIRE(c.ok());
  ImportOptions o;
  o.antarctica_level = 6;
  o.levels = {1, 2, 3};   // lakes become water surfaces of their own, level-3 islands their holes
  o.gamma = sm::testing::constant_accuracy(30e3);
  auto m = build_coast_model(std::move(*c), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  double min_lat = 0;
  for (auto p : m->curves[m->loops[m->surfaces[0].outer].curves[0]].ll) min_lat = std::min(min_lat, p.lat);
  CHECK(min_lat < -85);   // the grounding line reaches 85.2S (the ice front 78.6S)
  CHECK(m->report.count(RepairKind::UnitedIslands) >= 1);
  CHECK(m->surfaces.size() > 100);   // the ocean and the lakes
  check_model(*m);
}

TEST_CASE("import: the same input gives the same model, bit for bit") {
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(5000);
  o.repair.close_straits = true;
  auto a = build_coast_model(load("northsea_scheldt_f.txt"), o);
  auto b = build_coast_model(load("northsea_scheldt_f.txt"), o);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  REQUIRE(a->curves.size() == b->curves.size());
  for (std::size_t i = 0; i < a->curves.size(); ++i) {
    REQUIRE(a->curves[i].uv.size() == b->curves[i].uv.size());
    for (std::size_t k = 0; k < a->curves[i].uv.size(); ++k) CHECK(a->curves[i].uv[k] == b->curves[i].uv[k]);
  }
  const auto ia = a->report.items(), ib = b->report.items();
  REQUIRE(ia.size() == ib.size());
  for (std::size_t i = 0; i < ia.size(); ++i) CHECK(ia[i].text == ib[i].text);
}

// The curves' (u,v) points and the surfaces (each hole's outer loop) are made on the
// threads (import.cpp's set_uv and assign_holes): 1, 2 and 3 threads give the model of the
// serial import, loop for loop and point for point. The lakes (level 2) are outer loops
// beside the ocean's (round Antarctica), so the islands choose among several outers.
TEST_CASE("import: every thread count gives the serial model, surfaces and points alike") {
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(20e3);
  o.levels = {1, 2};
  auto read = read_gshhs(std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b");
  REQUIRE(read.ok());
  const Coastline source = std::move(*read);
  o.threads = 1;
  auto serial = build_coast_model(source, o);
  REQUIRE_MESSAGE(serial.ok(), (serial.ok() ? "" : serial.error().to_string()));
  REQUIRE(serial->surfaces.size() > 1);
  std::size_t holes = 0;
  for (const CoastSurface& s : serial->surfaces) holes += s.holes.size();
  REQUIRE(holes > 100);
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    o.threads = threads;
    auto m = build_coast_model(source, o);
    REQUIRE(m.ok());
    REQUIRE(m->surfaces.size() == serial->surfaces.size());
    for (std::size_t s = 0; s < m->surfaces.size(); ++s) {
      CHECK(m->surfaces[s].outer == serial->surfaces[s].outer);
      CHECK(m->surfaces[s].holes == serial->surfaces[s].holes);
    }
    CHECK(m->unassigned == serial->unassigned);
    REQUIRE(m->loops.size() == serial->loops.size());
    for (std::size_t l = 0; l < m->loops.size(); ++l) CHECK(m->loops[l].curves == serial->loops[l].curves);
    REQUIRE(m->curves.size() == serial->curves.size());
    for (std::size_t c = 0; c < m->curves.size(); ++c) {
      const CoastCurve& a = m->curves[c];
      const CoastCurve& b = serial->curves[c];
      REQUIRE(a.uv.size() == b.uv.size());
      bool same = a.ll.size() == b.ll.size();
      for (std::size_t k = 0; same && k < a.uv.size(); ++k)
        same = a.uv[k] == b.uv[k] && a.ll[k].lon == b.ll[k].lon && a.ll[k].lat == b.ll[k].lat;
      CHECK(same);
    }
    const auto ia = m->report.items(), ib = serial->report.items();
    REQUIRE(ia.size() == ib.size());
    for (std::size_t i = 0; i < ia.size(); ++i) CHECK(ia[i].text == ib[i].text);
  }
}
