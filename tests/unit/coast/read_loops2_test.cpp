// loops2 reader: the standalone file, a real GB ring re-expressed in every Coordinate
// option, and hostile text.
#include "coast/read_loops2.h"

#include <doctest/doctest.h>

#include <cmath>

#include <GeographicLib/TransverseMercator.hpp>
#include <fmt/format.h>

#include "coast/read_lonlat_text.h"

using namespace sm;
using namespace sm::coast;

TEST_CASE("loops2: the standalone file equals its GMT text twin") {
  auto a = read_loops2(std::string(SM_TEST_DATA) + "/coast/gb_islands_loops2.txt");
  auto b = read_lonlat_text(std::string(SM_TEST_DATA) + "/coast/gb_islands_f.txt");
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  REQUIRE(a->rings.size() == b->rings.size());
  for (std::size_t i = 0; i < a->rings.size(); ++i) {
    REQUIRE(a->rings[i].pts.size() == b->rings[i].pts.size());
    for (std::size_t k = 0; k < a->rings[i].pts.size(); ++k) {
      CHECK(a->rings[i].pts[k].lon == b->rings[i].pts[k].lon);
      CHECK(a->rings[i].pts[k].lat == b->rings[i].pts[k].lat);
    }
  }
}

TEST_CASE("loops2: radians, UTM and cartesian coordinates") {
  auto gb = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(gb.ok());
  const Ring& ring = gb->rings[5];
  std::string rad = fmt::format("{} 1\n", ring.pts.size()), utm = rad;
  const GeographicLib::TransverseMercator tm(6378137.0, (6378137.0 - 6356752.3142) / 6378137.0, 0.9996);
  for (auto p : ring.pts) {
    rad += fmt::format("{:.17g} {:.17g}\n", p.lon * geo::kDegToRad, p.lat * geo::kDegToRad);
    double x, y;
    tm.Forward(-3.0, p.lat, p.lon, x, y);   // zone 30: central meridian 3W
    utm += fmt::format("{:.6f} {:.6f}\n", x + 500000.0, y);
  }
  auto r = read_loops2_string(rad, "rad.txt", {Loops2Coordinate::LonLatRadians});
  Loops2Options uo;
  uo.coordinate = Loops2Coordinate::Utm;
  uo.utm_zone = 30;
  auto u = read_loops2_string(utm, "utm.txt", uo);
  REQUIRE(r.ok());
  REQUIRE(u.ok());
  REQUIRE(r->rings[0].pts.size() == ring.pts.size());
  REQUIRE(u->rings[0].pts.size() == ring.pts.size());
  for (std::size_t k = 0; k < ring.pts.size(); ++k) {
    CHECK(r->rings[0].pts[k].lon == doctest::Approx(ring.pts[k].lon).epsilon(1e-12));
    CHECK(u->rings[0].pts[k].lat == doctest::Approx(ring.pts[k].lat).epsilon(1e-9));
    CHECK(u->rings[0].pts[k].lon == doctest::Approx(ring.pts[k].lon).epsilon(1e-8));
  }
  auto c = read_loops2_string("3 1\n1 0\n0 1\n-1 -1\n", "c.txt", {Loops2Coordinate::Cartesian});
  REQUIRE(c.ok());
  CHECK(c->rings[0].pts[1].lon == doctest::Approx(90));
  CHECK(c->rings[0].pts[2].lon == doctest::Approx(225));  // contiguous with 90, i.e. -135
  CHECK(parse_loops2_coordinate("lonlat_degrees") == Loops2Coordinate::LonLatDegrees);
  CHECK_FALSE(parse_loops2_coordinate("polar").has_value());
}

TEST_CASE("loops2: hostile input") {
  CHECK_FALSE(read_loops2_string("", "e.txt").ok());
  CHECK_FALSE(read_loops2_string("2 0\n0 0\n1 1", "noeol.txt").ok());
  CHECK_FALSE(read_loops2_string("3 1\n0 0\n1 1\n", "short.txt").ok());           // truncated block
  CHECK_FALSE(read_loops2_string("3 2\n0 0\n1 1\n1 0\n", "closed.txt").ok());     // closed must be 0/1
  CHECK_FALSE(read_loops2_string("99999999999 1\n0 0\n", "absurd.txt").ok());
  CHECK_FALSE(read_loops2_string("2 0\nnan 0\n1 1\n", "nan.txt").ok());
  CHECK_FALSE(read_loops2_string("2 0\n0 91\n1 1\n", "lat.txt").ok());
  Loops2Options uo;
  uo.coordinate = Loops2Coordinate::Utm;
  CHECK_FALSE(read_loops2_string("1 0\n500000 0\n", "zone.txt", uo).ok());     // no zone given
  auto r = read_loops2_string("2 0\n0 0\n1 1\n2 0\n0 0\nx 1\n", "second.txt");
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().record == 1);
  CHECK(r.error().message.find("line 6") != std::string::npos);
}
