// Repair on small synthetic shorelines whose flaws are in the source data itself.
#include "coast/repair.h"

#include <doctest/doctest.h>

#include "coast/import.h"

using namespace sm;
using namespace sm::coast;

namespace {
AccuracyFn constant(double g) {
  return [g](std::span<const Vec3>, std::span<double> out) {
    for (double& x : out) x = g;
  };
}

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
  o.gamma = constant(10);
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

TEST_CASE("repair: a tiny island overlapping another is dropped; a large overlap is an error") {
  const std::vector<geo::LonLat> big{{0, 50}, {1, 50}, {1, 51}, {0, 51}};
  // 100 m square straddling the east coast of `big`.
  const std::vector<geo::LonLat> tiny{{0.9995, 50.5}, {1.0008, 50.5}, {1.0008, 50.5009}, {0.9995, 50.5009}};
  ImportOptions o;
  o.gamma = constant(80);   // the tiny square's sides (~95 m) survive; its perimeter is < 5 gamma
  auto m = build_coast_model(with_ocean({big, tiny}), o);
  REQUIRE_MESSAGE(m.ok(), (m.ok() ? "" : m.error().to_string()));
  CHECK(m->report.count(RepairKind::DroppedIsland) == 1);
  CHECK(m->surfaces[0].holes.size() == 1);
  const std::vector<geo::LonLat> other{{0.5, 50.5}, {1.5, 50.5}, {1.5, 51.5}, {0.5, 51.5}};
  auto bad = build_coast_model(with_ocean({big, other}), o);
  REQUIRE_FALSE(bad.ok());
  REQUIRE(bad.error().where.has_value());
  CHECK(bad.error().message.find("cross") != std::string::npos);
}
