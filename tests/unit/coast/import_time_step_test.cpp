// Mesh.MinTimeStep at the import (coast/import.h: min_time_step with depth_at): a passage
// narrower than dt sqrt(g H) at its own depth is closed, with the step it would have set;
// a KeepOpen passage narrower than that is kept and marked as missing the step.
#include "coast/import.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/constant_accuracy.h"
#include "coast/passages.h"

using namespace sm;
using namespace sm::coast;

namespace {

constexpr double kTsW = 0.01;      // degrees: the mouth of the inlet, about 1112 m
constexpr double kTsG = 9.81;

// A straight coast along lat 0 with a dead-end inlet 0.5 degrees deep whose sides run
// kTsW apart: in a mesh its mouth is crossed by one element, a sliver when kTsW is small.
Coastline ts_inlet() {
  Coastline c;
  c.file = "inlet";
  const double h = kTsW / 2;
  const geo::LonLat corners[] = {{-2, -2}, {2, -2}, {2, 0}, {h, 0}, {h, -0.5}, {-h, -0.5}, {-h, 0}, {-2, 0}};
  Ring r;
  const std::size_t n = std::size(corners);
  for (std::size_t i = 0; i < n; ++i) {
    const geo::LonLat a = corners[i], b = corners[(i + 1) % n];
    const int k = std::max(1, static_cast<int>(std::ceil(std::hypot(b.lon - a.lon, b.lat - a.lat) / 0.02)));
    for (int j = 0; j < k; ++j) r.pts.push_back({a.lon + (b.lon - a.lon) * j / k, a.lat + (b.lat - a.lat) * j / k});
  }
  c.rings.push_back(std::move(r));
  return c;
}

ImportOptions ts_options(double dt, double depth) {
  ImportOptions o;
  o.gamma = testing::constant_accuracy(300);
  o.region = LonLatBox{-1, 1, -1, 1};
  o.min_time_step = dt;
  o.depth_at = [depth](geo::LonLat) { return depth; };
  return o;
}

// The inlet's width as the kernel measures it: the distance between its two sides.
double ts_width() {
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  return uv_point_segment_metres(ps.param_from_lonlat({-kTsW / 2, -0.2}), ps.param_from_lonlat({kTsW / 2, -0.1}),
                                 ps.param_from_lonlat({kTsW / 2, -0.3}), geo::kEarthRadius);
}

const RepairEntry* ts_find(const CoastModel& m, RepairKind k) {
  for (const RepairEntry& e : m.report.repair)
    if (e.kind == k) return &e;
  return nullptr;
}

}  // namespace

TEST_CASE("import time step: an inlet narrower than dt sqrt(g H) is closed, with its step; a hair wider stays") {
  const double depth = 40;
  const double w = ts_width();
  const double step = w / std::sqrt(kTsG * depth);   // the step one element across sets
  CHECK(step == doctest::Approx(55.6).epsilon(0.01));
  auto open = build_coast_model(ts_inlet(), ts_options(step * (1 - 1e-3), depth));
  REQUIRE(open.ok());
  CHECK(open->report.count(RepairKind::ClosedPassage) + open->report.count(RepairKind::NarrowWater) == 0);
  auto closed = build_coast_model(ts_inlet(), ts_options(step * (1 + 1e-3), depth));
  REQUIRE(closed.ok());
  // The inlet is filled: no coast point left down it.
  std::size_t inside = 0;
  for (const CoastCurve& c : closed->curves)
    for (geo::LonLat p : c.ll) inside += p.lat < -0.05 && std::abs(p.lon) < 0.1;
  CHECK(inside == 0);
  CHECK(closed->report.count(RepairKind::ClosedPassage) + closed->report.count(RepairKind::NarrowWater) >= 1);
  if (const RepairEntry* e = ts_find(*closed, RepairKind::ClosedPassage)) {
    CHECK(e->value == doctest::Approx(w).epsilon(1e-6));
    CHECK(e->step == doctest::Approx(step).epsilon(1e-6));
  }
}

TEST_CASE("import time step: the width follows the depth of the place") {
  // 1112 m across in 10 m of water is a 112 s step, in 1000 m an 11.2 s one: at dt 30 s
  // the deep inlet is closed, the shallow one kept.
  const double w = ts_width();
  auto shallow = build_coast_model(ts_inlet(), ts_options(30, 10));
  REQUIRE(shallow.ok());
  CHECK(shallow->report.count(RepairKind::ClosedPassage) + shallow->report.count(RepairKind::NarrowWater) == 0);
  auto deep = build_coast_model(ts_inlet(), ts_options(30, 1000));
  REQUIRE(deep.ok());
  CHECK(deep->report.count(RepairKind::ClosedPassage) + deep->report.count(RepairKind::NarrowWater) >= 1);
  CHECK(w / std::sqrt(kTsG * 10) > 30);
  CHECK(w / std::sqrt(kTsG * 1000) < 30);
}

TEST_CASE("import time step: a KeepOpen inlet too narrow for dt stays open, marked as missing the step") {
  ImportOptions o = ts_options(100, 40);
  o.passages.keep_open = {{0, -0.25}};
  auto m = build_coast_model(ts_inlet(), o);
  REQUIRE(m.ok());
  CHECK(m->report.count(RepairKind::ClosedPassage) == 0);
  const RepairEntry* kept = ts_find(*m, RepairKind::KeptOpen);
  REQUIRE(kept != nullptr);
  CHECK(kept->step_unmet);
  CHECK(kept->step == doctest::Approx(kept->value / std::sqrt(kTsG * 40)).epsilon(1e-9));
  bool told = false;
  for (const ReportLine& l : m->report.items()) told = told || (l.kept_open && l.step_unmet);
  CHECK(told);
}
