// GMT's binned GSHHG netCDF files, read with the netCDF C API. Layout (GMT's
// gmt_shore.c, GSHHG 2.3.x): the globe is cut into bin_nx x bin_ny square bins of
// Bin_size_in_minutes, numbered row by row from the North-West; bin b holds the
// N_segments_in_a_bin[b] segments from Id_of_first_segment_in_a_bin[b]; a segment's
// Embedded_npts_levels_exit_entry word packs its point count (bits 9 and up), level
// (bits 6-8), entry side (3-5) and exit side (0-2; 4: closed inside the bin), its points
// start at Id_of_first_point_in_a_segment and are unsigned 1/65535 fractions of the bin
// side from its South-West corner; Id_of_GSHHS_ID names the polygon it is a piece of.
// Polygons carry their full-resolution area (km^2, what GMT's -A compares). GSHHG 2.3
// holds two Antarcticas: Embedded_ANT_flag marks the ice-front segments (stored with
// level 1), the grounding-line ones are stored with level 6.
#include "coast/read_gshhg_binned.h"

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <mutex>
#include <fmt/format.h>

#include "base/netcdf_lock.h"
#include "base/parallel.h"
#include "field/netcdf_header.h"

namespace sm::coast {

namespace {

constexpr std::int64_t kSteps = 65535;   // a bin's side in quantisation steps
constexpr int kLevelIce = 5, kLevelGround = 6;
/// A deflated HDF5 chunk expands at most about 1032 times: no array the file can really
/// hold is larger than this many elements per byte of file (hostile headers declare more).
constexpr std::uint64_t kMaxExpansion = 1100;

/// A failure of the read, turned into the CoastError at the top.
struct Fail {
  std::string message;
  std::int64_t record = -1;
};

class NcFile {
 public:
  NcFile(const std::string& path, std::uint64_t bytes) : bytes_(bytes) {
    status_ = nc_open(path.c_str(), NC_NOWRITE, &id_);
  }
  ~NcFile() {
    if (status_ == NC_NOERR) nc_close(id_);
  }
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;
  int status() const { return status_; }

  /// A one-dimensional variable of the given type; its length.
  std::uint64_t vector(const char* name, nc_type type, int& var) const {
    if (nc_inq_varid(id_, name, &var) != NC_NOERR) throw Fail{fmt::format("no variable '{}'", name)};
    nc_type t{};
    int nd = 0;
    check(nc_inq_vartype(id_, var, &t), name);
    check(nc_inq_varndims(id_, var, &nd), name);
    if (t != type) throw Fail{fmt::format("variable '{}' has netCDF type {}, expected {}", name, t, type)};
    if (nd != 1) throw Fail{fmt::format("variable '{}' has {} dimensions, expected 1", name, nd)};
    int dim = 0;
    std::size_t len = 0;
    check(nc_inq_vardimid(id_, var, &dim), name);
    check(nc_inq_dimlen(id_, dim, &len), name);
    if (len > kMaxExpansion * bytes_ + 16)
      throw Fail{fmt::format("variable '{}' declares {} values in a file of {} bytes", name, len, bytes_)};
    return len;
  }
  bool has(const char* name) const {
    int v = 0;
    return nc_inq_varid(id_, name, &v) == NC_NOERR;
  }
  int scalar(const char* name) const {
    int var = 0;
    if (vector(name, NC_INT, var) != 1) throw Fail{fmt::format("variable '{}' is not a scalar", name)};
    int v = 0;
    const std::size_t at = 0;
    check(nc_get_var1_int(id_, var, &at, &v), name);
    return v;
  }
  /// Values [start, start + out.size()) of a variable whose length is `expect`.
  template <class T>
  void read(const char* name, std::uint64_t expect, std::size_t start, std::vector<T>& out) const {
    read(name, expect, start, out.size(), out.data());
  }
  template <class T>
  void read(const char* name, std::uint64_t expect, std::size_t start, std::size_t count, T* out) const {
    int var = 0;
    const std::uint64_t len = vector(name, type_of<T>(), var);
    if (len != expect)
      throw Fail{fmt::format("variable '{}' has {} values where the file declares {}", name, len, expect)};
    if (start > len || count > len - start)
      throw Fail{fmt::format("values {}..{} of '{}' lie past its end ({})", start, start + count, name, len)};
    if (count == 0) return;
    check(get(var, start, count, out), name);
  }

 private:
  template <class T>
  static nc_type type_of() {
    if constexpr (std::is_same_v<T, int>) return NC_INT;
    else if constexpr (std::is_same_v<T, short>) return NC_SHORT;
    else if constexpr (std::is_same_v<T, double>) return NC_DOUBLE;
    else return NC_BYTE;
  }
  int get(int var, std::size_t start, std::size_t count, int* p) const {
    return nc_get_vara_int(id_, var, &start, &count, p);
  }
  int get(int var, std::size_t start, std::size_t count, short* p) const {
    return nc_get_vara_short(id_, var, &start, &count, p);
  }
  int get(int var, std::size_t start, std::size_t count, double* p) const {
    return nc_get_vara_double(id_, var, &start, &count, p);
  }
  int get(int var, std::size_t start, std::size_t count, signed char* p) const {
    return nc_get_vara_schar(id_, var, &start, &count, p);
  }
  static void check(int status, const char* what) {
    if (status != NC_NOERR) throw Fail{fmt::format("reading '{}': {}", what, nc_strerror(status))};
  }

  int id_ = -1;
  int status_ = NC_NOERR;
  std::uint64_t bytes_ = 0;
};

/// One piece of a polygon in one bin.
struct Piece {
  std::int32_t polygon;
  std::int32_t seg;        // segment index in the file
  std::int32_t bin;
  std::int32_t level;      // the ring level it gives
  std::int64_t start;      // first point
  std::int32_t n;          // points
  bool closed;             // entry/exit 4: the whole polygon inside the bin
};

/// Points as whole quantisation steps over the globe: x from lon 0 eastward, y from the
/// North Pole southward to the bin's corner then northward by dy (the file's own order),
/// so that the shared end points of pieces in neighbouring bins compare exactly.
struct BinGrid {
  std::int64_t nx = 0, ny = 0;   // bins
  double bsize = 0, scale = 0;   // degrees

  std::uint64_t key(std::int32_t bin, std::uint16_t dx, std::uint16_t dy) const {
    const std::int64_t col = bin % nx, row = bin / nx;
    const std::int64_t x = (col * kSteps + dx) % (nx * kSteps);   // longitudes modulo 360
    const std::int64_t y = (ny - 1 - row) * kSteps + dy;
    return (static_cast<std::uint64_t>(x) << 32) | static_cast<std::uint64_t>(y);
  }
  // The degrees as GMT computes them (corner + steps x scale), so that the values equal
  // those of `gmt coast` to the last bit where possible.
  geo::LonLat lonlat(std::int32_t bin, std::uint16_t dx, std::uint16_t dy) const {
    const std::int64_t col = bin % nx, row = bin / nx;
    return {static_cast<double>(col) * bsize + dx * scale, 90.0 - static_cast<double>(row + 1) * bsize + dy * scale};
  }
};

std::string missing_file_message(const std::string& path) {
  std::string msg = "no such file";
  const std::string base = std::filesystem::path(path).filename().string();
  if (base.size() == 17 && base.starts_with("binned_GSHHS_") && base.ends_with(".nc")) {
    if (const char* pkg = gshhg_package(base[13]))
      msg += fmt::format(": GSHHG resolution '{}' comes with the Debian package {} (apt-get install {})", base[13], pkg,
                         pkg);
  }
  return msg;
}

// The file's tables, each array checked against the counts the file declares.
struct BinnedTables {
  BinGrid grid;
  int n_bin = 0, n_seg = 0, n_pt = 0, n_poly = 0;
  std::vector<int> first_seg;       // per bin
  std::vector<short> bin_nseg;      // per bin
  std::vector<int> info, seg_start, seg_poly;   // per segment
  std::vector<signed char> ant;     // per segment: the ice-front flag
  std::vector<double> area;         // per polygon, km^2
};

// Sizes: every array's length must be the count the file declares for it.
BinnedTables read_sizes(const NcFile& nc) {
  BinnedTables t;
  const int bin_size = nc.scalar("Bin_size_in_minutes");
  const int bin_nx = nc.scalar("N_bins_in_360_longitude_range");
  const int bin_ny = nc.scalar("N_bins_in_180_degree_latitude_range");
  t.n_bin = nc.scalar("N_bins_in_file");
  t.n_seg = nc.scalar("N_segments_in_file");
  t.n_pt = nc.scalar("N_points_in_file");
  t.n_poly = nc.scalar("N_polygons_in_file");
  if (bin_size <= 0 || bin_nx <= 0 || bin_ny <= 0 || std::int64_t{bin_nx} * bin_size != 360 * 60 ||
      std::int64_t{bin_ny} * bin_size != 180 * 60)
    throw Fail{fmt::format("bins of {} minutes, {} x {}, do not tile the globe", bin_size, bin_nx, bin_ny)};
  if (std::int64_t{t.n_bin} != std::int64_t{bin_nx} * bin_ny)
    throw Fail{fmt::format("{} bins where {} x {} are declared", t.n_bin, bin_nx, bin_ny)};
  if (t.n_seg < 0 || t.n_pt < 0 || t.n_poly < 0)
    throw Fail{fmt::format("negative counts: {} segments, {} points, {} polygons", t.n_seg, t.n_pt, t.n_poly)};
  t.grid.nx = bin_nx;
  t.grid.ny = bin_ny;
  t.grid.bsize = bin_size / 60.0;
  t.grid.scale = t.grid.bsize / 65535.0;
  return t;
}

// The bins own consecutive runs of the segments, in bin order, which together are all of
// them: every segment belongs to exactly one bin (checked, so the loops over a bin's
// segments are bounded by n_seg).
void read_bins(const NcFile& nc, BinnedTables& t) {
  const int n_bin = t.n_bin;
  t.first_seg.resize(static_cast<std::size_t>(n_bin));
  t.bin_nseg.resize(static_cast<std::size_t>(n_bin));
  nc.read("Id_of_first_segment_in_a_bin", static_cast<std::uint64_t>(n_bin), 0, t.first_seg);
  nc.read("N_segments_in_a_bin", static_cast<std::uint64_t>(n_bin), 0, t.bin_nseg);
  std::int64_t next = 0;
  for (int b = 0; b < n_bin; ++b) {
    if (t.first_seg[b] != next || t.bin_nseg[b] < 0)
      throw Fail{fmt::format("bin {} lists segments {}..+{}, expected to start at {}", b, t.first_seg[b], t.bin_nseg[b],
                             next),
                 b};
    next += t.bin_nseg[b];
  }
  if (next != t.n_seg) throw Fail{fmt::format("the bins hold {} segments where the file declares {}", next, t.n_seg)};
}

// The segments' headers (points, levels, sides, polygon, ice flag) and the polygons'
// areas, each segment checked against them.
void read_segments(const NcFile& nc, BinnedTables& t) {
  const auto ns = static_cast<std::size_t>(t.n_seg);
  t.info.resize(ns);
  t.seg_start.resize(ns);
  t.seg_poly.resize(ns);
  t.ant.assign(ns, 0);
  nc.read("Embedded_npts_levels_exit_entry_for_a_segment", ns, 0, t.info);
  nc.read("Id_of_first_point_in_a_segment", ns, 0, t.seg_start);
  nc.read("Id_of_GSHHS_ID", ns, 0, t.seg_poly);
  const bool two_antarcticas = nc.has("Embedded_ANT_flag");
  if (two_antarcticas) nc.read("Embedded_ANT_flag", ns, 0, t.ant);
  t.area.resize(static_cast<std::size_t>(t.n_poly));
  nc.read("The_km_squared_area_of_polygons", static_cast<std::uint64_t>(t.n_poly), 0, t.area);

  for (std::size_t s = 0; s < ns; ++s) {
    const auto rec = static_cast<std::int64_t>(s);
    const std::int64_t np = static_cast<std::uint32_t>(t.info[s]) >> 9;
    const int exit = t.info[s] & 7, entry = (t.info[s] >> 3) & 7;
    if (t.seg_poly[s] < 0 || t.seg_poly[s] >= t.n_poly)
      throw Fail{fmt::format("segment {} belongs to polygon {} of {}", s, t.seg_poly[s], t.n_poly), rec};
    if (t.seg_start[s] < 0 || np < 2 || t.seg_start[s] + np > t.n_pt)
      throw Fail{fmt::format("segment {}: points {}..+{} do not lie in the file's {}", s, t.seg_start[s], np, t.n_pt),
                 rec};
    if (entry > 4 || exit > 4 || (entry == 4) != (exit == 4))
      throw Fail{fmt::format("segment {}: entry side {} and exit side {} (0-3 or both 4)", s, entry, exit), rec};
    if (!std::isfinite(t.area[static_cast<std::size_t>(t.seg_poly[s])]))
      throw Fail{fmt::format("polygon {} has area {}", t.seg_poly[s], t.area[static_cast<std::size_t>(t.seg_poly[s])]),
                 rec};
  }
}

// The level a segment's ring gets, 0 when it is not wanted. Levels 5 and 6 may also be
// asked for in `levels` (the import keeps a ring whose level is listed there too).
class RingLevels {
 public:
  RingLevels(const BinnedTables& t, const GshhgBinnedOptions& opt) : t_(t), opt_(opt) {
    // The ice-front continent: the largest ice-flagged polygon. With the grounding line it
    // is replaced; every other ice-flagged polygon (islands without a shelf) stays, as in GMT.
    for (std::size_t s = 0; s < t.ant.size(); ++s)
      if (t.ant[s] && (continent_ < 0 || std::fabs(t.area[static_cast<std::size_t>(t.seg_poly[s])]) >
                                             std::fabs(t.area[static_cast<std::size_t>(continent_)])))
        continent_ = t.seg_poly[s];
    want_ice_ = opt.antarctica_level == kLevelIce || listed(kLevelIce);
    want_ground_ = opt.antarctica_level == kLevelGround || listed(kLevelGround);
  }
  int operator()(std::size_t s) const {
    int level = (t_.info[s] >> 6) & 7;
    if (t_.ant[s]) level = kLevelIce;
    if (std::fabs(t_.area[static_cast<std::size_t>(t_.seg_poly[s])]) < opt_.min_area_km2) return 0;
    if (level == kLevelIce) {
      if (want_ice_) return kLevelIce;
      if (want_ground_ && t_.seg_poly[s] != continent_) return kLevelGround;
      return 0;
    }
    if (level == kLevelGround) return want_ground_ ? kLevelGround : 0;
    if (level >= 1 && level <= 4) return listed(level) ? level : 0;
    throw Fail{fmt::format("segment {} has level {} (1-6)", s, level), static_cast<std::int64_t>(s)};
  }

 private:
  bool listed(int l) const { return std::find(opt_.levels.begin(), opt_.levels.end(), l) != opt_.levels.end(); }
  const BinnedTables& t_;
  const GshhgBinnedOptions& opt_;
  int continent_ = -1;
  bool want_ice_ = false, want_ground_ = false;
};

// The pieces kept, in bin order: the bins overlapping the region, then every polygon with
// a piece in one of them, each of its pieces at a level asked for.
std::vector<Piece> select_pieces(const BinnedTables& t, const GshhgBinnedOptions& opt, const RingLevels& ring_level) {
  const BinGrid& grid = t.grid;
  std::vector<char> polygon_wanted(static_cast<std::size_t>(t.n_poly), opt.region ? 0 : 1);
  if (opt.region) {
    const LonLatBox& box = *opt.region;
    for (int b = 0; b < t.n_bin; ++b) {
      const double south = 90.0 - static_cast<double>(b / grid.nx + 1) * grid.bsize;
      if (south > box.north || south + grid.bsize < box.south) continue;
      const double d =
          std::fmod(std::fmod(static_cast<double>(b % grid.nx) * grid.bsize - box.west, 360.0) + 360.0, 360.0);
      const double w = box.west + d;   // the bin's west side taken in [west, west + 360)
      if (!(box.east - box.west >= 360 || w <= box.east || w - 360 + grid.bsize >= box.west)) continue;
      for (int s = t.first_seg[b]; s < t.first_seg[b] + t.bin_nseg[b]; ++s)
        if (ring_level(static_cast<std::size_t>(s)) != 0) polygon_wanted[static_cast<std::size_t>(t.seg_poly[s])] = 1;
    }
  }
  std::vector<Piece> pieces;
  for (int b = 0; b < t.n_bin; ++b)
    for (int s = t.first_seg[b]; s < t.first_seg[b] + t.bin_nseg[b]; ++s) {
      const auto su = static_cast<std::size_t>(s);
      if (!polygon_wanted[static_cast<std::size_t>(t.seg_poly[su])]) continue;
      const int level = ring_level(su);
      if (level == 0) continue;
      pieces.push_back({t.seg_poly[su], s, b, level, t.seg_start[su],
                        static_cast<std::int32_t>(static_cast<std::uint32_t>(t.info[su]) >> 9), (t.info[su] & 7) == 4});
    }
  return pieces;
}

// The points of the pieces kept, as steps from their bin's corner: all at once for the
// whole globe, else in runs of nearby segments (one netCDF call per run rather than per
// segment).
struct BinPoints {
  const BinGrid& grid;
  std::vector<short> dx, dy;
  std::uint16_t ux(std::int64_t i) const { return static_cast<std::uint16_t>(dx[static_cast<std::size_t>(i)]); }
  std::uint16_t uy(std::int64_t i) const { return static_cast<std::uint16_t>(dy[static_cast<std::size_t>(i)]); }
  std::uint64_t start_key(const Piece& p) const { return grid.key(p.bin, ux(p.start), uy(p.start)); }
  std::uint64_t end_key(const Piece& p) const { return grid.key(p.bin, ux(p.start + p.n - 1), uy(p.start + p.n - 1)); }
};

void read_points(const NcFile& nc, const BinnedTables& t, const std::vector<Piece>& pieces, BinPoints& pts) {
  std::vector<std::pair<std::int64_t, std::int64_t>> spans;   // [start, end)
  spans.reserve(pieces.size());
  for (const Piece& p : pieces) spans.emplace_back(p.start, p.start + p.n);
  std::sort(spans.begin(), spans.end());
  std::vector<std::pair<std::int64_t, std::int64_t>> runs;
  for (const auto& s : spans) {
    if (!runs.empty() && s.first <= runs.back().second + 65536)
      runs.back().second = std::max(runs.back().second, s.second);
    else
      runs.push_back(s);
  }
  pts.dx.assign(static_cast<std::size_t>(t.n_pt), 0);
  pts.dy.assign(static_cast<std::size_t>(t.n_pt), 0);
  for (const auto& [a, e] : runs) {   // straight into place: the points are 2 x 22 MB at full resolution
    const auto at = static_cast<std::size_t>(a), count = static_cast<std::size_t>(e - a);
    nc.read("Relative_longitude_from_SW_corner_of_bin", static_cast<std::uint64_t>(t.n_pt), at, count,
            pts.dx.data() + at);
    nc.read("Relative_latitude_from_SW_corner_of_bin", static_cast<std::uint64_t>(t.n_pt), at, count,
            pts.dy.data() + at);
  }
}

// A point of a piece: its bin and its index in the file's point arrays.
struct At {
  std::int32_t bin;
  std::int64_t i;
};

// One polygon's pieces [p0, p1) joined head to tail into cycles: a piece ends where the
// next one starts, on the side of the bin they share. `starts` and `used` are scratch.
void join_pieces(const std::vector<Piece>& pieces, std::size_t p0, std::size_t p1, const BinPoints& pts,
                 std::vector<std::pair<std::uint64_t, std::uint32_t>>& starts, std::vector<char>& used,
                 std::vector<std::vector<At>>& cycles) {
  const BinGrid& grid = pts.grid;
  auto key_at = [&](const At& a) { return grid.key(a.bin, pts.ux(a.i), pts.uy(a.i)); };
  const std::size_t n = p1 - p0;
  starts.clear();
  for (std::size_t k = p0; k < p1; ++k)
    starts.emplace_back(pts.start_key(pieces[k]), static_cast<std::uint32_t>(k - p0));
  std::sort(starts.begin(), starts.end());
  used.assign(n, 0);
  cycles.clear();
  // Each round closes one cycle and uses at least one piece: at most n rounds, and the
  // steps of all rounds together are at most n.
  for (std::size_t first = 0, left = n; left > 0;) {
    while (used[first]) ++first;
    std::vector<At>& chain = cycles.emplace_back();
    const Piece& f = pieces[p0 + first];
    if (f.closed && n != 1)
      throw Fail{fmt::format("polygon {} has a piece closed inside bin {} and {} others", f.polygon, f.bin, n - 1),
                 f.seg};
    const std::uint64_t ring_start = pts.start_key(f);
    std::size_t cur = first;
    for (std::size_t step = 0;; ++step) {
      const Piece& p = pieces[p0 + cur];
      used[cur] = 1;
      --left;
      // Consecutive repeated points (GMT's crude Antarctica has some) are kept once.
      for (std::int64_t i = 0; i < p.n; ++i)
        if (chain.empty() || key_at(chain.back()) != grid.key(p.bin, pts.ux(p.start + i), pts.uy(p.start + i)))
          chain.push_back({p.bin, p.start + i});
      const std::uint64_t e = pts.end_key(p);
      if (p.closed || e == ring_start) break;
      auto it = std::lower_bound(starts.begin(), starts.end(), std::make_pair(e, std::uint32_t{0}));
      while (it != starts.end() && it->first == e && used[it->second]) ++it;
      if (it == starts.end() || it->first != e || step + 1 >= n) {
        const geo::LonLat at = grid.lonlat(p.bin, pts.ux(p.start + p.n - 1), pts.uy(p.start + p.n - 1));
        throw Fail{fmt::format("the pieces of polygon {} do not join into a ring: no piece starts where segment {} "
                               "(bin {}) ends, at lon {:.6f} lat {:.6f}",
                               p.polygon, p.seg, p.bin, at.lon, at.lat),
                   p.seg};
      }
      cur = it->second;
    }
    // A closed ring does not repeat its first point.
    if (chain.size() > 1 && key_at(chain.front()) == key_at(chain.back())) chain.pop_back();
  }
}

// Where a polygon's outline touches itself on a bin side (an excursion of one vertex into
// the next bin and back, P -> Q -> P), the pieces close more than one cycle through P:
// each is spliced into the first cycle at its shared point, which gives GMT's one ring. A
// cycle sharing no point stays a ring of its own.
void splice_touching_cycles(const BinPoints& pts, std::vector<std::vector<At>>& cycles) {
  auto key_at = [&](const At& a) { return pts.grid.key(a.bin, pts.ux(a.i), pts.uy(a.i)); };
  for (std::size_t c = 1; c < cycles.size(); ++c) {
    std::vector<At>& main = cycles.front();
    std::vector<At>& sub = cycles[c];
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    keys.reserve(sub.size());
    for (std::size_t k = 0; k < sub.size(); ++k) keys.emplace_back(key_at(sub[k]), k);
    std::sort(keys.begin(), keys.end());
    for (std::size_t m = 0; m < main.size(); ++m) {
      auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key_at(main[m]), std::size_t{0}));
      if (it == keys.end() || it->first != key_at(main[m])) continue;
      std::rotate(sub.begin(), sub.begin() + static_cast<std::ptrdiff_t>(it->second), sub.end());
      sub.push_back(main[m]);   // back at P
      sub.erase(sub.begin());   // main[m] is P already
      main.insert(main.begin() + static_cast<std::ptrdiff_t>(m + 1), sub.begin(), sub.end());
      sub.clear();
      break;
    }
  }
}

// One polygon's cycles as rings in lon/lat (f: its first piece).
void emit_rings(const BinnedTables& t, const BinPoints& pts, const Piece& f, const std::vector<std::vector<At>>& cycles,
                Coastline& out) {
  const BinGrid& grid = pts.grid;
  auto key_at = [&](const At& a) { return grid.key(a.bin, pts.ux(a.i), pts.uy(a.i)); };
  const std::int64_t half_turn = grid.nx * kSteps / 2;   // x of lon 180 (nx is even: 360 / bin side)
  for (const std::vector<At>& chain : cycles) {
    if (chain.empty()) continue;
    // A ring round the pole starts on the dateline, as in GSHHS and GMT's exports.
    std::size_t rot = chain.size();
    for (std::size_t k = 0; k < chain.size() && rot == chain.size(); ++k)
      if (static_cast<std::int64_t>(key_at(chain[k]) >> 32) == half_turn) rot = k;
    Ring r;
    r.id = f.polygon;
    r.level = f.level;
    r.record = static_cast<std::size_t>(f.seg);
    r.area_km2 = std::fabs(t.area[static_cast<std::size_t>(f.polygon)]);
    r.pts.reserve(chain.size());
    for (const At& a : chain) r.pts.push_back(grid.lonlat(a.bin, pts.ux(a.i), pts.uy(a.i)));
    if (rot < chain.size() && std::fabs(longitude_winding(r.pts)) > 180) {
      std::rotate(r.pts.begin(), r.pts.begin() + static_cast<std::ptrdiff_t>(rot), r.pts.end());
      r.pts.front().lon = 180;
    }
    normalise_ring(r);
    out.rings.push_back(std::move(r));
  }
}

Coastline read(const std::string& path, const GshhgBinnedOptions& opt, std::uint64_t bytes) {
  const NcFile nc(path, bytes);
  if (nc.status() != NC_NOERR) throw Fail{fmt::format("cannot open as netCDF: {}", nc_strerror(nc.status()))};
  BinnedTables t = read_sizes(nc);
  read_bins(nc, t);
  read_segments(nc, t);
  const RingLevels ring_level(t, opt);
  std::vector<Piece> pieces = select_pieces(t, opt, ring_level);
  BinPoints pts{t.grid, {}, {}};
  read_points(nc, t, pieces, pts);
  // Pieces by polygon (bin order kept inside one), then each polygon's pieces joined into
  // rings.
  std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.polygon < b.polygon; });
  // The polygons are independent: runs of them on threads, each run's rings joined in
  // polygon order (a failure is the first polygon's, by run order, as on one thread).
  std::vector<std::size_t> polygon_first;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    if (p == 0 || pieces[p].polygon != pieces[p - 1].polygon) polygon_first.push_back(p);
  const std::size_t n_polygons = polygon_first.size();
  polygon_first.push_back(pieces.size());
  constexpr std::size_t kChunk = 512;   // polygons
  std::vector<Coastline> parts((n_polygons + kChunk - 1) / kChunk);
  parallel_for_chunks(resolve_thread_count(opt.threads), n_polygons, kChunk, [&](std::size_t begin, std::size_t end) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> starts;   // (start key, piece) of one polygon
    std::vector<char> used;
    std::vector<std::vector<At>> cycles;
    for (std::size_t g = begin; g < end; ++g) {
      const std::size_t p0 = polygon_first[g], p1 = polygon_first[g + 1];
      join_pieces(pieces, p0, p1, pts, starts, used, cycles);
      splice_touching_cycles(pts, cycles);
      emit_rings(t, pts, pieces[p0], cycles, parts[begin / kChunk]);
    }
  });
  Coastline out;
  out.file = path;
  std::size_t rings = 0;
  for (const Coastline& part : parts) rings += part.rings.size();
  out.rings.reserve(rings);
  for (Coastline& part : parts) std::move(part.rings.begin(), part.rings.end(), std::back_inserter(out.rings));
  return out;
}

}  // namespace

bool is_gshhg_resolution(std::string_view r) {
  return r.size() == 1 && std::string_view("clihf").find(r[0]) != std::string_view::npos;
}

std::string gshhg_binned_file(char resolution, std::string_view dir) {
  return fmt::format("{}/binned_GSHHS_{}.nc", dir, resolution);
}

const char* gshhg_package(char resolution) {
  switch (resolution) {
    case 'c':
    case 'l': return "gmt-gshhg-low";
    case 'i':
    case 'h': return "gmt-gshhg-high";
    case 'f': return "gmt-gshhg-full";
    default: return nullptr;
  }
}

Result<Coastline> read_gshhg_binned(const std::string& path, const GshhgBinnedOptions& opt) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return CoastError{path, -1, missing_file_message(path), {}};
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) return CoastError{path, -1, fmt::format("cannot read: {}", ec.message()), {}};
  // A classic-format file (GMT's older .cdf) could declare huge lists in a small header.
  if (auto why = field::check_netcdf_header_counts(path)) return CoastError{path, -1, *why, {}};
  const std::lock_guard<std::mutex> lock(base::netcdf_lock());   // libnetcdf is not thread-safe
  try {
    return read(path, opt, bytes);
  } catch (const Fail& f) {
    return CoastError{path, f.record, f.message, {}};
  } catch (const std::bad_alloc&) {
    return CoastError{path, -1, "out of memory for the sizes the file declares", {}};
  }
}

}  // namespace sm::coast
