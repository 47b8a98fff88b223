// Coarsening with gamma(x): spacing rule, closing rule, dropping rules, areas.
#include "coast/coarsen.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/clean.h"
#include "coast/read_gshhs.h"
#include "coast/read_lonlat_text.h"
#include "coast/region.h"
#include "coast/constant_accuracy.h"

using namespace sm;
using namespace sm::coast;


TEST_CASE("coarsen: kept points are at least gamma apart, closing included") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(c.ok());
  clean(*c);
  const double R = geo::kEarthRadius;
  for (double g : {15e3, 1.5e3}) {
    CoarsenOptions o;
    o.gamma = sm::testing::constant_accuracy(g);
    auto r = coarsen(c->rings, o);
    REQUIRE(r.ok());
    for (const CoarseRing& cr : r->rings) {
      const auto& p = cr.ring.pts;
      // (an open piece shorter than gamma keeps its two ends anyway)
      for (std::size_t k = 1; k < cr.keep.size(); ++k)
        if (cr.ring.closed || cr.keep.size() > 2) CHECK(chord(p[cr.keep[k - 1]], p[cr.keep[k]], R) >= g);
      if (cr.ring.closed) {
        CHECK(cr.keep.size() >= 3);
        CHECK(chord(p[cr.keep.back()], p[cr.keep.front()], R) >= g);
      } else {
        CHECK(cr.keep.front() == 0);                 // open pieces keep both ends
        CHECK(cr.keep.back() == p.size() - 1);
      }
    }
    CHECK(r->points_out < r->points_in);
  }
}

TEST_CASE("coarsen: a variable gamma keeps more points where it is small") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(c.ok());
  clean(*c);
  std::vector<Ring> gb{c->rings[0]};
  CoarsenOptions o;
  // 1 km south of 53N, 20 km north of it (x,y,z on the sphere of radius R).
  o.gamma = [](std::span<const Vec3> pts, std::span<double> g) {
    for (std::size_t i = 0; i < pts.size(); ++i)
      g[i] = std::asin(pts[i].z / norm(pts[i])) * geo::kRadToDeg < 53 ? 1e3 : 20e3;
  };
  auto r = coarsen(gb, o);
  REQUIRE(r.ok());
  std::size_t south = 0, north = 0;
  for (auto k : r->rings[0].keep) (r->rings[0].ring.pts[k].lat < 53 ? south : north)++;
  CHECK(south > 5 * north);
}

TEST_CASE("coarsen: MinArea, bad gamma, spherical areas") {
  auto c = read_gshhs(std::string(SM_DATA_DIR) + "/gshhs/gshhs_f_gb_ireland_generated.b");
  REQUIRE(c.ok());
  // The generated file's header areas are spherical areas on the authalic sphere.
  for (std::size_t i : {0u, 1u, 57u}) {
    const Ring& r = c->rings[i];
    CHECK(ring_area_km2(r.pts, 6371.0072) == doctest::Approx(r.area_km2).epsilon(1e-6));
  }
  CHECK(c->rings[0].area_km2 == doctest::Approx(218585).epsilon(1e-3));   // GB, PROVENANCE.md
  CoarsenOptions o;
  o.gamma = sm::testing::constant_accuracy(150);
  o.min_area_km2 = 10;
  auto r = coarsen(c->rings, o);
  REQUIRE(r.ok());
  std::size_t below = 0;
  for (const auto& d : r->dropped) below += d.reason == DropReason::BelowMinArea;
  std::size_t expect = 0;
  for (const Ring& ring : c->rings) expect += ring_area_km2(ring.pts, geo::kEarthRadius * 1e-3) < 10;
  CHECK(below == expect);
  CHECK(below > 2000);
  for (double bad : {0.0, -1.0, std::nan("")}) {
    o.gamma = sm::testing::constant_accuracy(bad);
    CHECK_FALSE(coarsen(c->rings, o).ok());
  }
  CHECK_FALSE(coarsen(c->rings, CoarsenOptions{}).ok());   // no field
}

TEST_CASE("coarsen: Antarctica keeps its pole-side area") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(c.ok());
  clean(*c);
  orient_rings(c->rings);
  for (const Ring& r : c->rings)
    if (r.wraps_pole) {
      const double a = ring_area_km2(r.pts, 6371.0);
      CHECK(a > 12e6);   // ice-front Antarctica: about 13.7 million km2
      CHECK(a < 15e6);
    }
}

TEST_CASE("coarsen and clean: the same rings for every thread count, the field called as with one") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/world_i_A100.txt");
  REQUIRE(c.ok());
  // A field that varies with the place and counts its calls: the calls (their sizes, in
  // order) must be those of one thread, from the calling thread.
  auto run = [&](int threads, std::vector<std::size_t>& calls) {
    Coastline copy = *c;
    const CleanReport rep = clean(copy, threads);
    CoarsenOptions o;
    o.threads = threads;
    o.min_area_km2 = 50;
    o.gamma = [&calls](std::span<const Vec3> p, std::span<double> g) {
      calls.push_back(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) g[i] = 20e3 + 15e3 * std::sin(1e-6 * p[i].x) * std::cos(1e-6 * p[i].z);
    };
    auto r = coarsen(copy.rings, o);
    REQUIRE(r.ok());
    return std::make_pair(rep.entries.size(), std::move(*r));
  };
  std::vector<std::size_t> calls1, calls4;
  const auto one = run(1, calls1);
  const auto four = run(4, calls4);
  CHECK(calls1 == calls4);
  CHECK(one.first == four.first);
  REQUIRE(one.second.rings.size() == four.second.rings.size());
  CHECK(one.second.dropped.size() == four.second.dropped.size());
  CHECK(one.second.points_out == four.second.points_out);
  CHECK(one.second.dropped.size() > 0);
  for (std::size_t k = 0; k < one.second.rings.size(); ++k) {
    CHECK(one.second.rings[k].keep == four.second.rings[k].keep);
    CHECK(one.second.rings[k].ring.record == four.second.rings[k].ring.record);
  }
}
