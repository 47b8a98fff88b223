// GMT multi-segment text reader on every data/gshhg file, plus hostile text.
#include "coast/read_lonlat_text.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include "scratch_dir.h"

using namespace sm;
using namespace sm::coast;

namespace {
const std::string kLonLatTextDir = std::string(SM_DATA_DIR) + "/gshhg/";


std::size_t file_points(const Coastline& c) {
  std::size_t n = 0;
  for (const Ring& r : c.rings) n += r.pts.size() + (r.closed && !r.wraps_pole ? 1 : 0);
  return n;
}
}  // namespace

TEST_CASE("lonlat text: every shared file matches its announced totals") {
  struct F { const char* name; std::size_t segs, open, points; int wraps; };
  const F files[] = {{"world_c.txt", 743, 0, 7899, 1},          {"world_l.txt", 5741, 0, 59124, 1},
                     {"world_i_A100.txt", 1440, 0, 192842, 1},  {"gb_ireland_f.txt", 2894, 2, 152836, 0},
                     {"northsea_scheldt_f.txt", 627, 18, 59375, 0}, {"gbr_lizard_f.txt", 1561, 9, 72749, 0},
                     {"arctic_i_A10.txt", 2117, 16, 89145, 0},  {"canadian_arctic_h.txt", 13158, 13, 165689, 0}};
  for (const F& f : files) {
    CAPTURE(f.name);
    auto c = read_lonlat_text(kLonLatTextDir + f.name);
    REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : c.error().to_string()));
    CHECK(c->rings.size() == f.segs);
    std::size_t open = 0;
    int wraps = 0;
    for (const Ring& r : c->rings) open += !r.closed, wraps += r.wraps_pole;
    CHECK(open == f.open);
    CHECK(wraps == f.wraps);
    // Antarctica's ring in the text stores 180 and -180 (one point twice on the sphere).
    CHECK(file_points(*c) + static_cast<std::size_t>(f.wraps) == f.points);
  }
}

TEST_CASE("lonlat text: regions, dateline rings, Antarctica") {
  auto gb = read_lonlat_text(kLonLatTextDir + "gb_ireland_f.txt");
  REQUIRE(gb.ok());
  REQUIRE(gb->region.has_value());
  CHECK(gb->region->west == -11);
  CHECK(gb->region->east == 2);
  CHECK(gb->region->south == 49);
  CHECK(gb->region->north == 61);
  CHECK(gb->rings[0].pts.size() == 49304);  // GB, closing point not repeated
  auto w = read_lonlat_text(kLonLatTextDir + "world_c.txt");
  REQUIRE(w.ok());
  CHECK_FALSE(w->region.has_value());  // -Rd is the whole globe
  auto extent = [](const Ring& r) {
    double lo = 1e9, hi = -1e9;
    for (auto p : r.pts) lo = std::min(lo, p.lon), hi = std::max(hi, p.lon);
    return std::pair{lo, hi};
  };
  // The segments that reach past +-180 (data/README.md).
  CHECK(extent(w->rings[0]).second == doctest::Approx(190.326085));
  CHECK(extent(w->rings[77]).first == doctest::Approx(-181.004).epsilon(1e-4));
  const auto it = std::find_if(w->rings.begin(), w->rings.end(), [](const Ring& r) { return r.wraps_pole; });
  REQUIRE(it != w->rings.end());
  CHECK(longitude_winding(it->pts) == -360.0);
  for (auto p : it->pts) CHECK(p.lat < -60);
}

TEST_CASE("lonlat text: the cut-down standalone file") {
  auto c = read_lonlat_text(std::string(SM_TEST_DATA) + "/coast/gb_islands_f.txt");
  REQUIRE(c.ok());
  CHECK(c->rings.size() == 4);
  CHECK(c->rings[0].id == 1001);
  for (const Ring& r : c->rings) CHECK(r.closed);
}

TEST_CASE("lonlat text: hostile input is a located error") {
  const std::string good = sm::testing::read_all(std::string(SM_TEST_DATA) + "/coast/gb_islands_f.txt");
  SUBCASE("truncated: the announced totals catch it") {
    for (std::size_t cut : {good.size() - 1, good.size() - 25, good.size() / 2, good.size() / 5}) {
      CAPTURE(cut);
      auto r = read_lonlat_text_string(std::string_view(good).substr(0, cut), "t.txt");
      CHECK_FALSE(r.ok());
    }
  }
  SUBCASE("NaN, inf and garbage coordinates") {
    for (const char* bad : {"nan 50.0", "-4.0 inf", "-4.0 fifty", "-4.0", "-4.0 50.0 7", "1e999 2"}) {
      const std::string t = "> seg=1 npts=1 closed=0\n" + std::string(bad) + "\n";
      auto r = read_lonlat_text_string(t, "bad.txt");
      REQUIRE_FALSE(r.ok());
      CHECK(r.error().record == 0);
      CHECK(r.error().message.find("line 2") != std::string::npos);
    }
  }
  SUBCASE("absurd npts") {
    auto r = read_lonlat_text_string("> seg=1 npts=999999999999 closed=1\n0 0\n", "bad.txt");
    REQUIRE_FALSE(r.ok());
    auto r2 = read_lonlat_text_string("> seg=1 npts=-3 closed=1\n0 0\n", "bad.txt");
    REQUIRE_FALSE(r2.ok());
  }
  SUBCASE("npts mismatch names the segment") {
    auto r = read_lonlat_text_string("> seg=1 npts=3 closed=0\n0 0\n1 1\n> seg=2 npts=1 closed=0\n2 2\n", "m.txt");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().record == 0);
  }
  SUBCASE("latitude off the globe") {
    auto r = read_lonlat_text_string("> npts=1 closed=0\n10 95\n", "bad.txt");
    REQUIRE_FALSE(r.ok());
    REQUIRE(r.error().where.has_value());
    CHECK(r.error().where->lat == 95);
  }
  SUBCASE("empty and comment-only files") {
    CHECK_FALSE(read_lonlat_text_string("", "e.txt").ok());
    CHECK_FALSE(read_lonlat_text_string("# nothing\n\n", "e.txt").ok());
    CHECK_FALSE(read_lonlat_text("/nonexistent.txt").ok());
  }
  SUBCASE("a file without headers is one segment") {
    auto r = read_lonlat_text_string("0 0\n1 0\n1 1\n0 0\n", "xy.txt");
    REQUIRE(r.ok());
    CHECK(r->rings.size() == 1);
    CHECK(r->rings[0].closed);
    CHECK(r->rings[0].pts.size() == 3);
  }
}

namespace {
// Rings equal to the last bit (the block reader must read what the text reader reads).
bool same_coastline(const Coastline& a, const Coastline& b) {
  if (a.rings.size() != b.rings.size()) return false;
  for (std::size_t k = 0; k < a.rings.size(); ++k) {
    const Ring& x = a.rings[k];
    const Ring& y = b.rings[k];
    if (x.id != y.id || x.level != y.level || x.closed != y.closed || x.pts.size() != y.pts.size()) return false;
    for (std::size_t i = 0; i < x.pts.size(); ++i)
      if (x.pts[i].lon != y.pts[i].lon || x.pts[i].lat != y.pts[i].lat) return false;
  }
  return true;
}
}  // namespace

TEST_CASE("lonlat text: a file of many blocks reads as the same text in memory") {
  // Over 4 MB (several FileBlocks blocks), with CRLF lines, lines cut by the block ends
  // wherever they fall, numbers in every form the fast path and from_chars take.
  std::string text = "# -R-180/180/-90/90 test\n";
  const char* forms[] = {"%.6f %.6f", "%.3f %.9f", "%g %g", "%.2e %.17g", "+%.6f\t%.6f ", "%.0f. %.1f"};
  int seg = 0;
  for (int i = 0; text.size() < 9'000'000; ++i) {
    if (i % 5000 == 0) text += "> seg=" + std::to_string(++seg) + " level=1\r\n";
    char line[96];
    const double lon = -170.0 + 340.0 * std::fmod(i * 0.6180339887, 1.0);
    const double lat = -80.0 + 160.0 * std::fmod(i * 0.3819660113, 1.0);
    std::snprintf(line, sizeof line, forms[i % 6], lon, lat);
    text += line;
    text += i % 3 == 0 ? "\r\n" : "\n";
  }
  sm::testing::ScratchDir dir;
  const std::string path = dir / "big.txt";
  std::ofstream(path, std::ios::binary) << text;
  auto from_file = read_lonlat_text(path);
  auto from_text = read_lonlat_text_string(text, path);
  REQUIRE_MESSAGE(from_file.ok(), (from_file.ok() ? "" : from_file.error().to_string()));
  REQUIRE(from_text.ok());
  CHECK(from_file->rings.size() == static_cast<std::size_t>(seg));
  CHECK(same_coastline(*from_file, *from_text));
  REQUIRE(from_file->region.has_value());
  // Cut inside the last number: the same error from both.
  text.resize(text.size() - 3);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  auto cut_file = read_lonlat_text(path);
  auto cut_text = read_lonlat_text_string(text, path);
  REQUIRE_FALSE(cut_file.ok());
  REQUIRE_FALSE(cut_text.ok());
  CHECK(cut_file.error().message == cut_text.error().message);
  // A bad line deep in the file: the same located error.
  text += "\n";
  text.insert(text.size() / 2 + (text.size() / 2 - text.rfind('\n', text.size() / 2)), "1.5x 2\n");
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  auto bad_file = read_lonlat_text(path);
  auto bad_text = read_lonlat_text_string(text, path);
  REQUIRE_FALSE(bad_file.ok());
  REQUIRE_FALSE(bad_text.ok());
  CHECK(bad_file.error().to_string() == bad_text.error().to_string());
}
