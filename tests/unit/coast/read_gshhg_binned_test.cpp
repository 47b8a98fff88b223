// The binned GSHHG reader on the system's files (Debian gmt-gshhg-*), against the text
// exports of the same data made by `gmt coast` (data/gshhg/*.txt, data/PROVENANCE.md),
// and on corrupted copies written here.
#include "coast/read_gshhg_binned.h"

#include <doctest/doctest.h>
#include <fmt/format.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "coast/read_lonlat_text.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::coast;

namespace {

const std::string kGshhgTextDir = std::string(SM_SOURCE_DIR) + "/data/gshhg/";

bool gshhg_have(char r) { return std::filesystem::exists(gshhg_binned_file(r)); }

bool gshhg_near(geo::LonLat a, geo::LonLat b, double tol) {
  const double dl = std::fabs(std::remainder(a.lon - b.lon, 360.0));
  return dl <= tol && std::fabs(a.lat - b.lat) <= tol;
}

/// The same closed ring up to its start: b rotated so that it starts at a's first point.
bool gshhg_same_ring(const Ring& a, const Ring& b, double tol) {
  if (a.pts.size() != b.pts.size() || a.pts.empty()) return false;
  const std::size_t n = a.pts.size();
  for (std::size_t j = 0; j < n; ++j) {
    if (!gshhg_near(a.pts[0], b.pts[j], tol)) continue;
    bool all = true;
    for (std::size_t k = 0; k < n && all; ++k) all = gshhg_near(a.pts[k], b.pts[(j + k) % n], tol);
    if (all) return true;
  }
  return false;
}

struct GshhgMatch {
  std::size_t text = 0, binned = 0, matched = 0;
  std::vector<std::string> misses;
};

/// Rings of the text matched one to one with rings of the binned read (same points within
/// tol after rotation), looked up among the binned rings of the same point count.
GshhgMatch gshhg_match(const Coastline& text, const Coastline& binned, double tol) {
  GshhgMatch m;
  m.text = text.rings.size();
  m.binned = binned.rings.size();
  std::multimap<std::size_t, std::size_t> by_size;
  for (std::size_t i = 0; i < binned.rings.size(); ++i) by_size.emplace(binned.rings[i].pts.size(), i);
  std::vector<char> taken(binned.rings.size(), 0);
  for (std::size_t t = 0; t < text.rings.size(); ++t) {
    const Ring& r = text.rings[t];
    bool found = false;
    auto [lo, hi] = by_size.equal_range(r.pts.size());
    for (auto it = lo; it != hi && !found; ++it)
      if (!taken[it->second] && gshhg_same_ring(r, binned.rings[it->second], tol)) taken[it->second] = 1, found = true;
    if (found) ++m.matched;
    else if (m.misses.size() < 10)
      m.misses.push_back(fmt::format("text ring {} ({} points, from lon {} lat {}, wraps {})", t, r.pts.size(),
                                     r.pts[0].lon, r.pts[0].lat, r.wraps_pole));
  }
  return m;
}

}  // namespace

TEST_CASE("gshhg binned: crude world equals world_c.txt") {
  if (!gshhg_have('c')) return;
  auto text = read_lonlat_text(kGshhgTextDir + "world_c.txt");
  REQUIRE(text.ok());
  auto bin = read_gshhg_binned(gshhg_binned_file('c'));
  REQUIRE_MESSAGE(bin.ok(), (bin.ok() ? "" : bin.error().to_string()));
  const GshhgMatch m = gshhg_match(*text, *bin, 1e-5);
  for (const std::string& s : m.misses) MESSAGE(s);
  CHECK(m.binned == 743);
  CHECK(m.matched == 743);
}

TEST_CASE("gshhg binned: intermediate world, 100 km^2, equals world_i_A100.txt") {
  if (!gshhg_have('i')) return;
  auto text = read_lonlat_text(kGshhgTextDir + "world_i_A100.txt");
  REQUIRE(text.ok());
  GshhgBinnedOptions o;
  o.min_area_km2 = 100;
  auto bin = read_gshhg_binned(gshhg_binned_file('i'), o);
  REQUIRE_MESSAGE(bin.ok(), (bin.ok() ? "" : bin.error().to_string()));
  const GshhgMatch m = gshhg_match(*text, *bin, 1e-5);
  for (const std::string& s : m.misses) MESSAGE(s);
  CHECK(m.binned == 1440);
  CHECK(m.matched == 1440);
}

TEST_CASE("gshhg binned: a Region reads its bins' polygons whole (full resolution, Great Britain and Ireland)") {
  if (!gshhg_have('f')) return;
  auto text = read_lonlat_text(kGshhgTextDir + "gb_ireland_f.txt");
  REQUIRE(text.ok());
  GshhgBinnedOptions o;
  o.region = LonLatBox{-11, 2, 49, 61};
  auto bin = read_gshhg_binned(gshhg_binned_file('f'), o);
  REQUIRE_MESSAGE(bin.ok(), (bin.ok() ? "" : bin.error().to_string()));
  Coastline closed, inside;
  for (const Ring& r : text->rings)
    if (r.closed) closed.rings.push_back(r);
  for (const Ring& r : bin->rings) {
    bool in = true;
    for (const geo::LonLat& p : r.pts) in = in && p.lon >= -11 && p.lon <= 2 && p.lat >= 49 && p.lat <= 61;
    if (in) inside.rings.push_back(r);
  }
  CHECK(closed.rings.size() == 2892);
  const GshhgMatch m = gshhg_match(closed, inside, 1e-5);
  for (const std::string& s : m.misses) MESSAGE(s);
  CHECK(m.matched == 2892);
  CHECK(inside.rings.size() == 2892);
  // The rings the box cuts come whole: Eurasia (polygon 0) is there, up to the dateline.
  auto eurasia = std::find_if(bin->rings.begin(), bin->rings.end(), [](const Ring& r) { return r.id == 0; });
  REQUIRE(eurasia != bin->rings.end());
  CHECK(eurasia->pts.size() > 1000000);
  CHECK(bin->rings.size() < 4000);   // and not the whole world's 180,000
}
