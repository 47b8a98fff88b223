// Repair on small synthetic shorelines whose flaws are in the source data itself.
#include "coast/repair.h"

#include <doctest/doctest.h>

#include "coast/import.h"
#include "coast/read_lonlat_text.h"

#include <cmath>
#include "coast/constant_accuracy.h"

using namespace sm;
using namespace sm::coast;

namespace {

Coastline with_ocean(std::vector<std::vector<geo::LonLat>> islands) {
  Coastline c;
  c.file = "synthetic";
  Ring ant;   // a pole-wrapping ring as the ocean's outer boundary
  for (int i = 0; i < 36; ++i) ant.pts.push_back({180.0 - 10.0 * i, -70.0});
  ant.wraps_pole = true;
  c.rings.push_back(ant);
  std::size_t rec = 1;
  for (auto& pts : islands) {
    Ring r;
    r.pts = std::move(pts);
    r.record = rec;
    r.id = static_cast<std::int64_t>(rec++);
    c.rings.push_back(std::move(r));
  }
  return c;
}
}  // namespace

TEST_CASE("repair: a loop crossing itself in the source loses its twisted sliver") {
  // (0.6,51) -> (0.4,51.1) and (0.6,51.1) -> (0.4,51.0) cross at (0.5, 51.05).
  auto c = with_ocean({{{0, 50}, {1, 50}, {1, 51}, {0.6, 51}, {0.4, 51.1}, {0.6, 51.1}, {0.4, 51.0}, {0, 51}}});
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(10);
  // The control points as coarsening leaves them (the deviation bound would split the
  // data's long straight segments at the corners): the repair is what is tested.
  o.deviation.factor = 0;
  auto m = build_coast_model(std::move(c), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  REQUIRE(m->report.count(RepairKind::CutSliver) == 1);
  for (const auto& e : m->report.repair)
    if (e.kind == RepairKind::CutSliver) {
      CHECK(e.where.lon == doctest::Approx(0.5).epsilon(1e-3));
      CHECK(e.where.lat == doctest::Approx(51.05).epsilon(1e-4));
    }
  REQUIRE(m->surfaces[0].holes.size() == 1);
  CHECK(m->curves[m->loops[m->surfaces[0].holes[0]].curves[0]].ll.size() == 6);   // (0.4,51.1) and (0.6,51.1) cut out
}

TEST_CASE("repair: a tiny island overlapping another is dropped; one through a vertex of the outer loop is an error") {
  const std::vector<geo::LonLat> big{{0, 50}, {1, 50}, {1, 51}, {0, 51}};
  // 100 m square straddling the east coast of `big`.
  const std::vector<geo::LonLat> tiny{{0.9995, 50.5}, {1.0008, 50.5}, {1.0008, 50.5009}, {0.9995, 50.5009}};
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(80);   // the tiny square's sides (~95 m) survive; its perimeter is < 5 gamma
  auto m = build_coast_model(with_ocean({big, tiny}), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  CHECK(m->report.count(RepairKind::DroppedIsland) == 1);
  CHECK(m->surfaces[0].holes.size() == 1);
  // An island straddling the ring round the South Pole through its vertex (0, -70): a
  // touch plus crossings, which no rule unites.
  const std::vector<geo::LonLat> ice{{0, -70.5}, {1, -70.5}, {1, -69.5}, {0, -69.5}};
  o.gamma = sm::testing::constant_accuracy(1000);
  auto bad = build_coast_model(with_ocean({ice}), o);
  REQUIRE_FALSE(bad.ok());
  REQUIRE(bad.error().where.has_value());
  CHECK(bad.error().where->lat == doctest::Approx(-70).epsilon(1e-2));
  CHECK(bad.error().message.find("cross") != std::string::npos);
}

TEST_CASE("repair: a strait narrower than gamma is listed, or closed on request") {
  // Two 0.01-degree squares about 70 m apart (0.001 deg of longitude at 50N).
  const std::vector<geo::LonLat> a{{0, 50}, {0.01, 50}, {0.01, 50.01}, {0, 50.01}};
  const std::vector<geo::LonLat> b{{0.011, 50}, {0.021, 50}, {0.021, 50.01}, {0.011, 50.01}};
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(100);
  // The control points as coarsening leaves them (the deviation bound would split the
  // data's long straight segments at the corners): the repair is what is tested.
  o.deviation.factor = 0;
  auto open = build_coast_model(with_ocean({a, b}), o);
  REQUIRE(open.ok());
  REQUIRE(open->report.count(RepairKind::NarrowStrait) == 1);
  for (const auto& e : open->report.repair)
    if (e.kind == RepairKind::NarrowStrait) CHECK(e.value == doctest::Approx(71.6).epsilon(0.01));
  CHECK(open->surfaces[0].holes.size() == 2);
  o.repair.close_straits = true;
  auto closed = build_coast_model(with_ocean({a, b}), o);
  REQUIRE(closed.ok());
  CHECK(closed->report.count(RepairKind::MergedIslands) == 1);
  CHECK(closed->report.count(RepairKind::NarrowStrait) == 0);
  REQUIRE(closed->surfaces[0].holes.size() == 1);
  const auto& merged = closed->curves[closed->loops[closed->surfaces[0].holes[0]].curves[0]];
  CHECK(merged.ll.size() == 8);
  o.repair.strait_factor = 0.5;   // 50 m: the 72 m strait stays open
  auto wide = build_coast_model(with_ocean({a, b}), o);
  REQUIRE(wide.ok());
  CHECK(wide->report.count(RepairKind::MergedIslands) == 0);
}

TEST_CASE("repair: closing straits at 15 km joins Anglesey to Great Britain across the Menai Strait") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(c.ok());
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(15e3);
  o.repair.close_straits = true;
  auto m = build_coast_model(std::move(*c), o);
  REQUIRE(m.ok());
  bool menai = false;
  for (const auto& e : m->report.repair)
    if (e.kind == RepairKind::MergedIslands && std::abs(e.where.lon + 4.2) < 0.1 && std::abs(e.where.lat - 53.2) < 0.1)
      menai = true;
  CHECK(menai);
  CHECK(m->surfaces[0].holes.size() < 16);
}

TEST_CASE("repair: random self-crossing shorelines end in a model or an error, never a crash or a hang") {
  std::uint32_t seed = 7;
  auto rnd = [&seed] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
  int ok = 0, failed = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<std::vector<geo::LonLat>> islands;
    const int ni = 1 + trial % 6;
    for (int i = 0; i < ni; ++i) {
      std::vector<geo::LonLat> p;
      const double lon0 = 10 * rnd(), lat0 = 40 + 10 * rnd();
      const int n = 3 + static_cast<int>(rnd() * 30);
      for (int k = 0; k < n; ++k) p.push_back({lon0 + 2 * rnd(), lat0 + 2 * rnd()});
      islands.push_back(p);
    }
    ImportOptions o;
    o.gamma = sm::testing::constant_accuracy(1000 + 50e3 * rnd());
    o.repair.close_straits = trial % 2 == 1;
    auto m = build_coast_model(with_ocean(islands), o);
    if (m.ok()) {
      ++ok;
      CHECK(m->surfaces.size() == 1);
    } else {
      ++failed;
      CHECK_FALSE(m.error().message.empty());
    }
  }
  CHECK(ok + failed == 40);
}

TEST_CASE("repair: two islands overlapping in the source are united") {
  const std::vector<geo::LonLat> a{{0, 50}, {1, 50}, {1, 51}, {0, 51}};
  const std::vector<geo::LonLat> b{{0.5, 50.5}, {1.5, 50.5}, {1.5, 51.5}, {0.5, 51.5}};
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(1000);
  // The control points as coarsening leaves them (the deviation bound would split the
  // data's long straight segments at the corners): the repair is what is tested.
  o.deviation.factor = 0;
  auto m = build_coast_model(with_ocean({a, b}), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  CHECK(m->report.count(RepairKind::UnitedIslands) == 1);
  REQUIRE(m->surfaces[0].holes.size() == 1);
  const auto& u = m->curves[m->loops[m->surfaces[0].holes[0]].curves[0]];
  CHECK(u.ll.size() == 8);   // 6 corners of the union + 2 crossing points
  // Crossings of the (u,v) chords: a parallel is a circle in (u,v), so the crossing on
  // a lat = const side lies 0.0014 degree off it at this size.
  int near_cross = 0;
  for (auto p : u.ll) near_cross += (std::abs(p.lon - 1.0) < 1e-6 && std::abs(p.lat - 50.5) < 2e-3) ||
                                    (std::abs(p.lon - 0.5) < 1e-6 && std::abs(p.lat - 51.0) < 2e-3);
  CHECK(near_cross == 2);
  // Interleaved outlines cross at four places: the union has a lagoon, not one outline.
  const std::vector<geo::LonLat> c{{0.2, 49.5}, {0.8, 49.5}, {0.8, 51.5}, {0.2, 51.5}};
  const std::vector<geo::LonLat> d{{-0.5, 50.2}, {1.5, 50.2}, {1.5, 50.8}, {-0.5, 50.8}};
  auto x = build_coast_model(with_ocean({c, d}), o);
  if (x.ok()) CHECK(x->report.count(RepairKind::UnitedIslands) == 1);
}

TEST_CASE("repair: an island straddling the ring round the South Pole becomes part of Antarctica") {
  const std::vector<geo::LonLat> ice{{3, -70.5}, {4, -70.5}, {4, -69.5}, {3, -69.5}};
  ImportOptions o;
  o.gamma = sm::testing::constant_accuracy(1000);
  auto m = build_coast_model(with_ocean({ice}), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  CHECK(m->report.count(RepairKind::UnitedIslands) == 1);
  CHECK(m->surfaces[0].holes.empty());
  double north = -90;
  for (auto p : m->curves[m->loops[m->surfaces[0].outer].curves[0]].ll) north = std::max(north, p.lat);
  CHECK(north == doctest::Approx(-69.5));   // the island's north side is now Antarctica's coast
}

TEST_CASE("repair: an island merged across a strait gives its points up; the merged curve holds both") {
  // The two squares of the test above, as work curves (orientation and ocean left out:
  // handle_straits looks at the two holes only).
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  auto curve = [&](std::vector<geo::LonLat> pts) {
    WorkCurve c;
    c.periodic = true;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      c.uv.push_back(ps.param_from_lonlat(pts[i]));
      c.gamma.push_back(100);
      c.keep.push_back(static_cast<std::uint32_t>(i));
    }
    c.full = std::move(pts);
    return c;
  };
  std::vector<WorkCurve> curves{curve({{0, 50}, {0, 50.01}, {0.01, 50.01}, {0.01, 50}}),
                                curve({{0.011, 50}, {0.011, 50.01}, {0.021, 50.01}, {0.021, 50}})};
  std::vector<WorkLoop> loops{{{0}, true, false}, {{1}, true, false}};
  RepairOptions o;
  o.close_straits = true;
  std::vector<RepairEntry> log;
  handle_straits(curves, loops, o, log);
  REQUIRE(log.size() == 1);
  CHECK(log[0].kind == RepairKind::MergedIslands);
  REQUIRE(loops[0].dead != loops[1].dead);
  const WorkCurve& kept = curves[loops[0].dead ? 1 : 0];
  const WorkCurve& gone = curves[loops[0].dead ? 0 : 1];
  CHECK(kept.full.size() == 8);
  CHECK(kept.uv.size() == 8);
  CHECK(kept.gamma.size() == 8);
  CHECK(kept.keep.size() == 8);
  // Nothing reads a dead loop's curve again: its arrays are freed, capacity included.
  CHECK(gone.full.capacity() == 0);
  CHECK(gone.uv.capacity() == 0);
  CHECK(gone.gamma.capacity() == 0);
  CHECK(gone.keep.capacity() == 0);
  CHECK(gone.record == 0);
}
