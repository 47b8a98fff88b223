// GSHHS binary reader on the original 2.3.0 crude file, the two generated files, 1.x
// layouts rebuilt from the real records, and hostile bytes.
#include "coast/read_gshhs.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "coast/file_bytes.h"

using namespace sm;
using namespace sm::coast;

namespace {
const std::string kDir = std::string(SM_DATA_DIR) + "/gshhs/";

void put_be32(std::vector<unsigned char>& out, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(u >> s));
}
std::int32_t get_be32(const unsigned char* p) {
  return static_cast<std::int32_t>((std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
                                   (std::uint32_t{p[2]} << 8) | p[3]);
}
}  // namespace

TEST_CASE("gshhs: original GSHHG 2.3.0 crude file") {
  auto c = read_gshhs(kDir + "gshhs_c.b");
  REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : c.error().to_string()));
  CHECK(c->rings.size() == 1781);
  std::map<int, int> levels;
  std::size_t points = 0;
  for (const Ring& r : c->rings) {
    ++levels[r.level];
    points += r.pts.size() + 1;  // the file repeats the first point (Antarctica: stores both 180 and -180)
  }
  CHECK(points == 13044);
  CHECK(levels[1] == 739);
  CHECK(levels[2] == 993);
  CHECK(levels[3] == 24);
  CHECK(levels[5] == 5);
  CHECK(levels[6] == 20);
  const Ring& eurasia = c->rings[0];
  CHECK(eurasia.id == 0);
  CHECK(eurasia.area_km2 == doctest::Approx(50577990.9).epsilon(1e-9));
  // Contiguous longitudes: Eurasia runs from west of Greenwich past the dateline.
  double lo = 1e9, hi = -1e9;
  for (auto p : eurasia.pts) lo = std::min(lo, p.lon), hi = std::max(hi, p.lon);
  CHECK(lo == doctest::Approx(-9.500444).epsilon(1e-4));  // header extent (full resolution)
  CHECK(hi == doctest::Approx(190.359111).epsilon(1e-3));
  CHECK(lo >= -9.500444);
  CHECK(hi <= 190.359111);
  // Great Britain (id 15) crosses Greenwich: stored 359.x / 0.x, read contiguous.
  const Ring& gb = c->rings[15];
  REQUIRE(gb.id == 15);
  double glo = 1e9, ghi = -1e9;
  for (std::size_t i = 0; i < gb.pts.size(); ++i) {
    glo = std::min(glo, gb.pts[i].lon), ghi = std::max(ghi, gb.pts[i].lon);
    if (i > 0) CHECK(std::abs(gb.pts[i].lon - gb.pts[i - 1].lon) < 180);
  }
  CHECK(glo == doctest::Approx(-6.230861).epsilon(1e-3));
  CHECK(glo >= -6.230861);
  CHECK(ghi > 1.0);
  CHECK(ghi < 2.0);
  // Antarctica records are the only pole-wrapping rings, and they wind westwards.
  int wraps = 0;
  for (const Ring& r : c->rings)
    if (r.wraps_pole) {
      ++wraps;
      CHECK((r.level == 5 || r.level == 6));
      CHECK(longitude_winding(r.pts) == -360.0);
    }
  CHECK(wraps == 2);
}

TEST_CASE("gshhs: generated GB/Ireland and world_l files") {
  auto gb = read_gshhs(kDir + "gshhs_f_gb_ireland_generated.b");
  REQUIRE(gb.ok());
  std::size_t pts = 0;
  for (const Ring& r : gb->rings) pts += r.pts.size() + 1;
  CHECK(gb->rings.size() == 2892);
  CHECK(pts == 147990);
  auto w = read_gshhs(kDir + "gshhs_l_world_generated.b");
  REQUIRE(w.ok());
  CHECK(w->rings.size() == 5741);
  int l1 = 0, l5 = 0, wraps = 0;
  for (const Ring& r : w->rings) {
    l1 += r.level == 1;
    l5 += r.level == 5;
    wraps += r.wraps_pole;
  }
  CHECK(l1 == 5740);
  CHECK(l5 == 1);
  CHECK(wraps == 1);
}

TEST_CASE("gshhs: 1.x layouts rebuilt from the 2.3.0 records read the same") {
  auto bytes = read_file_bytes(kDir + "gshhs_c.b");
  REQUIRE(bytes.ok());
  const auto& b = *bytes;
  std::vector<unsigned char> v1flag, v1plain;
  for (std::size_t off = 0; off < b.size();) {
    std::array<std::int32_t, 11> h;
    for (int k = 0; k < 11; ++k) h[k] = get_be32(&b[off + 4 * k]);
    const std::int32_t flag = h[2];
    const std::int32_t flag16 = (flag & 0xFFFF) | (((flag >> 16) & 1) << 16) | (((flag >> 24) & 1) << 24);
    for (int k = 0; k < 8; ++k) put_be32(v1flag, k == 2 ? flag16 : k == 7 ? 1234 : h[k]);
    for (int k = 0; k < 8; ++k) put_be32(v1plain, k == 2 ? (flag & 255) : k == 7 ? 1234 : h[k]);
    v1plain.push_back(0), v1plain.push_back(static_cast<unsigned char>((flag >> 16) & 1));
    v1plain.push_back(0), v1plain.push_back(static_cast<unsigned char>((flag >> 24) & 1));
    const std::size_t body = static_cast<std::size_t>(h[1]) * 8;
    v1flag.insert(v1flag.end(), b.begin() + static_cast<long>(off + 44),
                  b.begin() + static_cast<long>(off + 44 + body));
    v1plain.insert(v1plain.end(), b.begin() + static_cast<long>(off + 44),
                   b.begin() + static_cast<long>(off + 44 + body));
    off += 44 + body;
  }
  auto ref = read_gshhs_bytes(b, "v2");
  auto a = read_gshhs_bytes(v1flag, "v1flag");
  auto p = read_gshhs_bytes(v1plain, "v1plain");
  REQUIRE(ref.ok());
  REQUIRE_MESSAGE(a.ok(), (a.ok() ? "" : a.error().to_string()));
  REQUIRE_MESSAGE(p.ok(), (p.ok() ? "" : p.error().to_string()));
  REQUIRE(a->rings.size() == ref->rings.size());
  REQUIRE(p->rings.size() == ref->rings.size());
  for (std::size_t i = 0; i < ref->rings.size(); i += 97) {
    CHECK(a->rings[i].level == ref->rings[i].level);
    CHECK(p->rings[i].level == ref->rings[i].level);
    CHECK(a->rings[i].pts.size() == ref->rings[i].pts.size());
    CHECK(p->rings[i].pts.back().lon == ref->rings[i].pts.back().lon);
    CHECK(a->rings[i].area_km2 == doctest::Approx(123.4));  // 1.x areas are 1/10 km2
  }
}

TEST_CASE("gshhs: hostile input is a located error") {
  auto bytes = read_file_bytes(kDir + "gshhs_c.b");
  REQUIRE(bytes.ok());
  const std::vector<unsigned char>& b = *bytes;
  SUBCASE("empty") {
    auto r = read_gshhs_bytes({}, "empty.b");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message.find("empty") != std::string::npos);
  }
  SUBCASE("missing file") {
    auto r = read_gshhs("/nonexistent/gshhs_x.b");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().file == "/nonexistent/gshhs_x.b");
  }
  SUBCASE("truncated inside the points of the last record") {
    std::vector<unsigned char> t(b.begin(), b.end() - 13);
    auto r = read_gshhs_bytes(t, "trunc.b");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().record == 1780);
    CHECK(r.error().file == "trunc.b");
  }
  SUBCASE("truncated inside a header") {
    std::vector<unsigned char> t(b.begin(), b.begin() + 44 + 8 * get_be32(&b[4]) + 20);
    auto r = read_gshhs_bytes(t, "trunc.b");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().record == 1);
  }
  SUBCASE("absurd and negative point counts") {
    for (std::int32_t n : {0x7FFFFFFF, -5, 1 << 28}) {
      std::vector<unsigned char> t = b;
      t[4] = static_cast<unsigned char>(n >> 24), t[5] = static_cast<unsigned char>(n >> 16);
      t[6] = static_cast<unsigned char>(n >> 8), t[7] = static_cast<unsigned char>(n);
      auto r = read_gshhs_bytes(t, "bad.b");
      REQUIRE_FALSE(r.ok());
      CHECK(r.error().record == 0);
    }
  }
  SUBCASE("latitude off the globe in a point") {
    std::vector<unsigned char> t = b;
    const std::size_t p = 44 + 4;  // latitude of the first point of record 0
    t[p] = 0x7F;
    auto r = read_gshhs_bytes(t, "bad.b");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().record == 0);
  }
  SUBCASE("random bytes") {
    std::vector<unsigned char> t(5000);
    std::uint32_t s = 12345;
    for (auto& c : t) c = static_cast<unsigned char>((s = s * 1664525u + 1013904223u) >> 24);
    CHECK_FALSE(read_gshhs_bytes(t, "noise.b").ok());
  }
}
