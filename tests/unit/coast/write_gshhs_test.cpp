// GSHHS writer: what it writes reads back through read_gshhs as the same rings (to the
// micro-degree the format holds), on real GSHHG data, and bad input is refused.
#include "coast/write_gshhs.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "coast/read_gshhs.h"
#include "coast/read_lonlat_text.h"

using namespace sm;
using namespace sm::coast;

namespace {

// Same rings, points equal to the micro-degree (longitudes modulo 360).
void check_same_rings(const Coastline& a, const Coastline& b) {
  REQUIRE(a.rings.size() == b.rings.size());
  for (std::size_t k = 0; k < a.rings.size(); ++k) {
    const Ring& x = a.rings[k];
    const Ring& y = b.rings[k];
    CHECK(x.level == y.level);
    CHECK(x.id == y.id);
    CHECK(x.wraps_pole == y.wraps_pole);
    REQUIRE(x.pts.size() == y.pts.size());
    for (std::size_t i = 0; i < x.pts.size(); ++i) {
      const double dlon = std::remainder(x.pts[i].lon - y.pts[i].lon, 360.0);
      if (std::abs(dlon) > 5e-7 || std::abs(x.pts[i].lat - y.pts[i].lat) > 5e-7) {
        FAIL_CHECK("ring " << k << " point " << i << " differs");
        return;
      }
    }
  }
}

}  // namespace

TEST_CASE("write_gshhs: GSHHG text (GB and Ireland, full) round trip") {
  auto text = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE_MESSAGE(text.ok(), (text.ok() ? "" : text.error().to_string()));
  // The file's box-closed rings are closed; keep those only (GSHHS holds closed rings).
  Coastline closed;
  for (const Ring& r : text->rings)
    if (r.closed) closed.rings.push_back(r);
  REQUIRE(closed.rings.size() > 100);
  auto bytes = gshhs_bytes(closed);
  REQUIRE(bytes.ok());
  std::size_t points = 0;
  for (const Ring& r : closed.rings) points += r.pts.size();
  CHECK(bytes->size() == 44 * closed.rings.size() + 8 * points);
  auto back = read_gshhs_bytes(*bytes, "mem");
  REQUIRE_MESSAGE(back.ok(), (back.ok() ? "" : back.error().to_string()));
  check_same_rings(closed, *back);
  // The header's area is the ring's spherical area: Great Britain is about 218,000 km^2.
  double largest = 0;
  for (const Ring& r : back->rings) largest = std::max(largest, r.area_km2);
  CHECK(largest == doctest::Approx(218000).epsilon(0.05));
}

TEST_CASE("write_gshhs: the original crude GSHHS file round trip (Antarctica round the pole)") {
  auto c = read_gshhs(std::string(SM_DATA_DIR) + "/gshhs/gshhs_c.b");
  REQUIRE(c.ok());
  auto bytes = gshhs_bytes(*c);
  REQUIRE(bytes.ok());
  auto back = read_gshhs_bytes(*bytes, "mem");
  REQUIRE_MESSAGE(back.ok(), (back.ok() ? "" : back.error().to_string()));
  check_same_rings(*c, *back);
  bool pole = false;
  for (const Ring& r : back->rings) pole = pole || r.wraps_pole;
  CHECK(pole);
}

TEST_CASE("write_gshhs: open rings, bad levels and points off the globe are refused") {
  Coastline c;
  c.file = "x";
  Ring r;
  r.pts = {{0, 0}, {1, 0}, {1, 1}};
  r.closed = false;
  c.rings.push_back(r);
  auto open = gshhs_bytes(c);
  REQUIRE_FALSE(open.ok());
  CHECK(open.error().record == 0);
  c.rings[0].closed = true;
  c.rings[0].level = 7;
  CHECK_FALSE(gshhs_bytes(c).ok());
  c.rings[0].level = 1;
  c.rings[0].pts[1].lat = 91;
  auto off = gshhs_bytes(c);
  REQUIRE_FALSE(off.ok());
  CHECK(off.error().where.has_value());
  c.rings[0].pts[1].lat = 0;
  CHECK(gshhs_bytes(c).ok());
  CHECK_FALSE(write_gshhs(c, "/nonexistent-dir/x.b").ok());
}
