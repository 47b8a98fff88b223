// Longitude bookkeeping of the neutral structure.
#include "coast/coastline.h"

#include <doctest/doctest.h>

using namespace sm;
using namespace sm::coast;

TEST_CASE("coastline: wrap, unwrap, winding, same point") {
  CHECK(wrap_delta(179, -179) == doctest::Approx(2));
  CHECK(wrap_delta(-179, 179) == doctest::Approx(-2));
  CHECK(wrap_delta(0, 180) == doctest::Approx(180));
  CHECK(wrap_delta(0, -180) == doctest::Approx(180));   // (-180, 180]
  std::vector<geo::LonLat> p{{359.5, 10}, {0.5, 10}, {0.5, 11}, {359.5, 11}};
  unwrap_longitudes(p);
  CHECK(p[0].lon == doctest::Approx(-0.5));   // mid-longitude brought into [-180, 180)
  CHECK(p[1].lon == doctest::Approx(0.5));
  CHECK(longitude_winding(p) == 0);
  std::vector<geo::LonLat> pole;
  for (int i = 0; i < 12; ++i) pole.push_back({180.0 - 30.0 * i, -70});
  unwrap_longitudes(pole);
  CHECK(longitude_winding(pole) == -360);
  CHECK(same_point({180, 5}, {-180, 5}));
  CHECK(same_point({10, 90}, {-70, 90}));
  CHECK_FALSE(same_point({10, 5}, {10, 5.000001}));
  Ring r;
  r.pts = {{180, -70}, {90, -71}, {0, -70}, {-90, -72}, {-180, -70}};
  normalise_ring(r);
  CHECK(r.pts.size() == 4);   // -180 is the first point again
  CHECK(r.wraps_pole);
  CoastError e{"f.b", 3, "bad", geo::LonLat{1.5, -2}};
  CHECK(e.to_string() == "f.b: record 3 (lon 1.500000, lat -2.000000): bad");
}
