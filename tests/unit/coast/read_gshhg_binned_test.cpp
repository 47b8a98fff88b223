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
#include <cstring>
#include <fstream>
#include <functional>
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
  // On two threads (runs of 512 polygons): the same rings in the same order.
  o.threads = 2;
  auto two = read_gshhg_binned(gshhg_binned_file('i'), o);
  REQUIRE(two.ok());
  REQUIRE(two->rings.size() == bin->rings.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < bin->rings.size(); ++k) {
    const Ring& a = bin->rings[k];
    const Ring& b = two->rings[k];
    differ += a.pts.size() != b.pts.size() || a.id != b.id || a.record != b.record || a.level != b.level;
    for (std::size_t i = 0; i < std::min(a.pts.size(), b.pts.size()); ++i)
      differ += a.pts[i].lon != b.pts[i].lon || a.pts[i].lat != b.pts[i].lat;
  }
  CHECK(differ == 0);
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

TEST_CASE("gshhg binned: Antarctica's two coasts and the other levels") {
  if (!gshhg_have('c')) return;
  auto count = [](const Coastline& c, int level, bool wraps) {
    return std::count_if(c.rings.begin(), c.rings.end(),
                         [&](const Ring& r) { return r.level == level && r.wraps_pole == wraps; });
  };
  GshhgBinnedOptions o;
  auto ice = read_gshhg_binned(gshhg_binned_file('c'), o);
  REQUIRE(ice.ok());
  CHECK(count(*ice, 5, true) == 1);
  CHECK(count(*ice, 6, true) == 0);
  o.antarctica_level = 6;
  auto ground = read_gshhg_binned(gshhg_binned_file('c'), o);
  REQUIRE(ground.ok());
  CHECK(count(*ground, 5, true) == 0);
  CHECK(count(*ground, 6, true) == 1);
  o.antarctica_level = 5;
  o.levels = {1, 6};   // as the import reads Levels: both coasts
  auto both = read_gshhg_binned(gshhg_binned_file('c'), o);
  REQUIRE(both.ok());
  CHECK(count(*both, 5, true) == 1);
  CHECK(count(*both, 6, true) == 1);
  o.antarctica_level = 0;
  o.levels = {1, 2, 3, 4};
  auto none = read_gshhg_binned(gshhg_binned_file('c'), o);
  REQUIRE(none.ok());
  CHECK(count(*none, 5, true) + count(*none, 6, true) + count(*none, 5, false) + count(*none, 6, false) == 0);
  CHECK(count(*none, 2, false) > 0);   // lakes
  for (const Ring& r : none->rings) CHECK(r.area_km2 >= 0);
}

namespace {

/// A copy of `src` as a classic netCDF file, with `edit` given each variable's values
/// (as bytes) before they are written: the corrupted files of the tests below.
void copy_netcdf(const std::string& src, const std::string& dst,
                 const std::function<void(const std::string&, std::vector<char>&)>& edit) {
  int in = -1, out = -1;
  REQUIRE(nc_open(src.c_str(), NC_NOWRITE, &in) == NC_NOERR);
  REQUIRE(nc_create(dst.c_str(), NC_CLOBBER | NC_64BIT_OFFSET, &out) == NC_NOERR);
  int ndims = 0, nvars = 0;
  nc_inq_ndims(in, &ndims);
  nc_inq_nvars(in, &nvars);
  for (int d = 0; d < ndims; ++d) {
    char name[NC_MAX_NAME + 1];
    std::size_t len = 0;
    nc_inq_dim(in, d, name, &len);
    int id = 0;
    REQUIRE(nc_def_dim(out, name, len, &id) == NC_NOERR);
  }
  for (int v = 0; v < nvars; ++v) {
    char name[NC_MAX_NAME + 1];
    nc_type t{};
    int nd = 0, dims[NC_MAX_VAR_DIMS], id = 0;
    nc_inq_var(in, v, name, &t, &nd, dims, nullptr);
    REQUIRE(nc_def_var(out, name, t, nd, dims, &id) == NC_NOERR);
  }
  REQUIRE(nc_enddef(out) == NC_NOERR);
  for (int v = 0; v < nvars; ++v) {
    char name[NC_MAX_NAME + 1];
    nc_type t{};
    int nd = 0, dims[NC_MAX_VAR_DIMS];
    nc_inq_var(in, v, name, &t, &nd, dims, nullptr);
    std::size_t n = 1, size = 0;
    for (int k = 0; k < nd; ++k) {
      std::size_t len = 0;
      nc_inq_dimlen(in, dims[k], &len);
      n *= len;
    }
    nc_inq_type(in, t, nullptr, &size);
    std::vector<char> bytes(n * size);
    REQUIRE(nc_get_var(in, v, bytes.data()) == NC_NOERR);
    edit(name, bytes);
    REQUIRE(nc_put_var(out, v, bytes.data()) == NC_NOERR);
  }
  nc_close(out);
  nc_close(in);
}

template <class T>
void set_value(std::vector<char>& bytes, std::size_t i, T v) {
  REQUIRE((i + 1) * sizeof(T) <= bytes.size());
  std::memcpy(bytes.data() + i * sizeof(T), &v, sizeof(T));
}

std::string read_error(const std::string& path) {
  auto r = read_gshhg_binned(path);
  if (r.ok()) return "";
  CHECK(r.error().file == path);
  return r.error().to_string();
}

}  // namespace

TEST_CASE("gshhg binned: a missing resolution names its Debian package") {
  testing::ScratchDir dir;
  for (char r : std::string("clihf")) {
    const std::string msg = read_error(gshhg_binned_file(r, dir.path.string()));
    CAPTURE(msg);
    CHECK(msg.find("no such file") != std::string::npos);
    CHECK(msg.find(gshhg_package(r)) != std::string::npos);
  }
  CHECK(read_error((dir.path / "other.nc").string()).find("apt-get") == std::string::npos);
  CHECK(std::string(gshhg_package('c')) == "gmt-gshhg-low");
  CHECK(std::string(gshhg_package('h')) == "gmt-gshhg-high");
  CHECK(std::string(gshhg_package('f')) == "gmt-gshhg-full");
  CHECK(gshhg_package('x') == nullptr);
  CHECK(is_gshhg_resolution("i"));
  CHECK_FALSE(is_gshhg_resolution("x"));
  CHECK_FALSE(is_gshhg_resolution("ll"));
}

TEST_CASE("gshhg binned: truncated and corrupted copies of the crude file are errors") {
  if (!gshhg_have('c')) return;
  testing::ScratchDir dir;
  const std::string crude = gshhg_binned_file('c');
  // Cut short: every length from nothing to all but the last byte refuses to open or read.
  {
    std::ifstream f(crude, std::ios::binary);
    const std::vector<char> all((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    for (std::size_t len : {std::size_t{0}, std::size_t{8}, std::size_t{512}, all.size() / 3, all.size() / 2,
                            all.size() - 100, all.size() - 1}) {
      CAPTURE(len);
      const std::string cut = (dir.path / fmt::format("cut_{}.nc", len)).string();
      std::ofstream(cut, std::ios::binary).write(all.data(), static_cast<std::streamsize>(len));
      CHECK_FALSE(read_error(cut).empty());
    }
  }
  // A faithful copy reads as the original, so the edits below are what the errors see.
  const std::string same = (dir.path / "same.nc").string();
  copy_netcdf(crude, same, [](const std::string&, std::vector<char>&) {});
  auto a = read_gshhg_binned(crude);
  auto b = read_gshhg_binned(same);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a->rings.size() == b->rings.size());
  struct Edit {
    const char* what;
    const char* var;
    std::function<void(std::vector<char>&)> change;
    const char* expect;
  };
  const Edit edits[] = {
      {"bins that do not tile the globe", "N_bins_in_360_longitude_range", [](auto& v) { set_value<int>(v, 0, 17); },
       "do not tile the globe"},
      {"a bin count unlike the dimensions", "N_bins_in_file", [](auto& v) { set_value<int>(v, 0, 100); }, "bins where"},
      {"more points declared than stored", "N_points_in_file", [](auto& v) { set_value<int>(v, 0, 20000); },
       "where the file declares"},
      {"a segment's points past the end", "Id_of_first_point_in_a_segment",
       [](auto& v) { set_value<int>(v, 7, 14137); }, "do not lie in the file's"},
      {"a bin's segments out of order", "Id_of_first_segment_in_a_bin", [](auto& v) { set_value<int>(v, 3, 2000); },
       "expected to start at"},
      {"a segment of a polygon that does not exist", "Id_of_GSHHS_ID", [](auto& v) { set_value<int>(v, 11, 99999); },
       "belongs to polygon"},
      {"a piece moved off its neighbour's end", "Relative_longitude_from_SW_corner_of_bin",
       [](auto& v) {   // the first point of every piece of the file, shifted by one step
         for (std::size_t i = 0; i < v.size() / 2; i += 1) {
           short x;
           std::memcpy(&x, v.data() + 2 * i, 2);
           if (x == 0) set_value<short>(v, i, 1);
         }
       },
       "do not join into a ring"},
      {"a level outside 1-6", "Embedded_npts_levels_exit_entry_for_a_segment",
       [](auto& v) {
         int w;
         std::memcpy(&w, v.data(), 4);
         set_value<int>(v, 0, (w & ~(7 << 6)) | (7 << 6));
       },
       "has level 7"},
  };
  for (const Edit& e : edits) {
    const std::string what = e.what;
    CAPTURE(what);
    const std::string bad = (dir.path / "bad.nc").string();
    copy_netcdf(crude, bad, [&](const std::string& name, std::vector<char>& bytes) {
      if (name == e.var) e.change(bytes);
    });
    const std::string msg = read_error(bad);
    CAPTURE(msg);
    CHECK(msg.find(e.expect) != std::string::npos);
  }
}

TEST_CASE("gshhg binned: the fuzz seed, a polygon cut by the dateline and a triangle inside one bin") {
  // The classic seed of the fuzz corpus, and the same CDL in HDF5's container (kept out of
  // the corpus: the fuzz entry skips HDF5, tests/fuzz/fuzz_gshhg_binned_entry.cpp).
  const std::string root = std::string(SM_SOURCE_DIR) + "/tests/";
  for (const char* f : {"fuzz/corpus_gshhg_binned/two_bins_classic.nc", "data/gshhg_binned/two_bins_nc4.nc"}) {
    CAPTURE(f);
    auto c = read_gshhg_binned(root + f);
    REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : c.error().to_string()));
    REQUIRE(c->rings.size() == 2);
    const Ring& a = c->rings[0];   // the two pieces joined across lon 180: 4 points
    CHECK(a.id == 0);
    CHECK(a.pts.size() == 4);
    CHECK_FALSE(a.wraps_pole);
    for (const geo::LonLat& p : a.pts) CHECK(std::fabs(p.lon - 180) < 90);   // contiguous across the dateline
    CHECK(a.area_km2 == 1000);
    const Ring& t = c->rings[1];
    CHECK(t.pts.size() == 3);
    CHECK(t.area_km2 == 50);
    GshhgBinnedOptions o;
    o.min_area_km2 = 100;
    auto big = read_gshhg_binned(root + f, o);
    REQUIRE(big.ok());
    CHECK(big->rings.size() == 1);
    o.region = LonLatBox{10, 20, 0, 10};   // bin 0 only: the polygon comes whole from both bins
    auto box = read_gshhg_binned(root + f, o);
    REQUIRE(box.ok());
    REQUIRE(box->rings.size() == 1);
    CHECK(box->rings[0].pts.size() == 4);
  }
}
