// Lon/lat grid readers (netCDF through libnetcdf, ESRI ASCII by hand) and
// bilinear interpolation.
#include "field/lonlat_grid.h"
#include "base/file_identity.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <mutex>

#include "base/netcdf_lock.h"
#include <numbers>
#include <sstream>

#include <fmt/format.h>
#include <netcdf.h>

#include "field/error.h"
#include "field/netcdf_header.h"

namespace sm::field {

namespace {

constexpr double kDeg = std::numbers::pi / 180;
// Bounds on a grid read from a file: LonLatGrid indexes sides with int, and
// 2^31 nodes (16 GiB of doubles) is far beyond any global relief model in use.
constexpr std::size_t kMaxGridSide = 2147483647;
constexpr std::uint64_t kMaxGridValues = std::uint64_t{1} << 31;

[[noreturn]] void file_error(const std::filesystem::path& file, const std::string& what) {
  FieldError e(FieldErrc::FileError, fmt::format("{}: {}", file.string(), what));
  e.file = file.string();
  e.reason = what;
  throw e;
}

/// Checks that `c`, the `role` ("longitude", "latitude") axis held by variable `name`, is
/// finite, strictly monotonic and evenly spaced, in that order, so that the message names
/// the first index that breaks the first rule (a NaN would otherwise pass every
/// comparison, and a step back would read as mere unevenness); returns (first, step),
/// step may be < 0.
std::pair<double, double> even_axis(const std::filesystem::path& file, std::string_view role,
                                    const std::string& name, const std::vector<double>& c) {
  if (c.size() < 2) file_error(file, fmt::format("{} axis '{}' needs at least 2 values", role, name));
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!std::isfinite(c[k]))
      file_error(file, fmt::format("{} axis '{}' holds {} at index {}", role, name, c[k], k));
  const bool rising = c[1] > c[0];
  for (std::size_t k = 1; k < c.size(); ++k) {
    if (c[k] == c[k - 1])
      file_error(file, fmt::format("{} axis '{}' repeats the value {} at index {} (as index {}): it must be "
                                   "strictly monotonic", role, name, c[k], k, k - 1));
    if ((c[k] > c[k - 1]) != rising)
      file_error(file, fmt::format("{} axis '{}' is not monotonic: value {} at index {} after {} at index {}",
                                   role, name, c[k], k, c[k - 1], k - 1));
  }
  const double step = (c.back() - c.front()) / static_cast<double>(c.size() - 1);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double expect = c.front() + step * static_cast<double>(k);
    if (!(std::fabs(c[k] - expect) <= 1e-3 * std::fabs(step)))
      file_error(file, fmt::format("{} axis '{}' is not evenly spaced: value {} at index {}, expected {} "
                                   "(the grid is read as regular)", role, name, c[k], k, expect));
  }
  return {c.front(), step};
}

// The file indices of the nodes within `window` {W, E, S, N} plus one on each side, for
// axes first + k step (k < n, step of either sign): columns c0 .. c0 + cn - 1 and rows
// r0 .. r0 + rn - 1, at least two of each; every column when the box crosses the grid's
// seam (the columns would wrap round the file's end). A box that misses the grid is an
// error.
void window_of(const std::filesystem::path& file, const std::vector<double>& w, double x0, double dx, std::size_t nx,
               double y0, double dy, std::size_t ny, std::size_t& c0, std::size_t& cn, std::size_t& r0,
               std::size_t& rn) {
  // Indices k with first + k step in [lo, hi], widened by one node and kept in 0 .. n-1.
  auto range = [&](double first, double step, std::size_t n, double lo, double hi, std::size_t& k0,
                   std::size_t& count) {
    double a = (lo - first) / step, b = (hi - first) / step;
    if (a > b) std::swap(a, b);
    const double last = static_cast<double>(n - 1);
    if (b < 0 || a > last)
      file_error(file, fmt::format("the window {{{}, {}, {}, {}}} holds no node of the grid", w[0], w[1], w[2],
                                   w[3]));
    double lo_k = std::max(0.0, std::floor(a) - 1), hi_k = std::min(last, std::ceil(b) + 1);
    if (hi_k - lo_k < 1) {   // one node in the box: its neighbour too, for the bilinear value
      if (lo_k > 0) lo_k -= 1;
      else hi_k += 1;
    }
    k0 = static_cast<std::size_t>(lo_k);
    count = static_cast<std::size_t>(hi_k - lo_k) + 1;
  };
  range(y0, dy, ny, w[2], w[3], r0, rn);
  const double step = std::fabs(dx);
  const double west = std::min(x0, x0 + dx * static_cast<double>(nx - 1));
  const double east = std::max(x0, x0 + dx * static_cast<double>(nx - 1));
  // The copy of the box (mod 360) that starts at or after the grid's west edge, and the
  // copy one turn west of it: the grid's columns meet one of them, both, or neither.
  const double shift = 360 * std::floor((w[0] - west) / 360);
  const double bw = w[0] - shift, be = w[1] - shift;
  const bool meets_east_copy = bw <= east, meets_west_copy = be - 360 >= west;
  const bool global = east - west + step >= 360 - 1e-9 * step;
  if (meets_east_copy && meets_west_copy) {
    c0 = 0, cn = nx;   // the box wraps round the grid's seam
  } else if (meets_east_copy) {
    if (global && be > east) c0 = 0, cn = nx;
    else range(x0, dx, nx, bw, be, c0, cn);
  } else if (meets_west_copy) {
    range(x0, dx, nx, bw - 360, be - 360, c0, cn);
  } else {
    file_error(file, fmt::format("the window {{{}, {}, {}, {}}} holds no node of the grid", w[0], w[1], w[2], w[3]));
  }
}

// The nodes must lie on the globe: latitudes in [-90, 90] and longitudes in
// [-540, 540] (a grid may run past +-180), with half a cell of slack for grids
// whose node rows stand for cells that touch a pole.
void check_extent(const std::filesystem::path& file, const LonLatGrid& g) {
  const double west = g.lon0, east = g.lon0 + g.dlon * (g.nlon - 1);
  const double south = g.lat0, north = g.lat0 + g.dlat * (g.nlat - 1);
  const double slack_lat = 0.5 * g.dlat + 1e-9, slack_lon = 0.5 * g.dlon + 1e-9;
  if (!(south >= -90 - slack_lat && north <= 90 + slack_lat))
    file_error(file, fmt::format("the grid's latitudes {} .. {} are not in [-90, 90]", south, north));
  if (!(west >= -540 - slack_lon && east <= 540 + slack_lon))
    file_error(file, fmt::format("the grid's longitudes {} .. {} are not in [-540, 540]", west, east));
}

}  // namespace

void LonLatGrid::detect_wrap() {
  period = 0;
  const double cols = 360.0 / dlon;
  const double p = std::round(cols);
  if (std::fabs(cols - p) < 1e-6 * cols && nlon >= static_cast<int>(p)) period = static_cast<int>(p);
}

int LonLatGrid::wrap(int i) const {
  if (period == 0) return i;
  i %= period;
  return i < 0 ? i + period : i;
}

LonLatGrid::Stencil LonLatGrid::stencil(double lon_deg, double lat_deg) const {
  Stencil st;
  double tj = std::clamp((lat_deg - lat0) / dlat, 0.0, static_cast<double>(nlat - 1));
  st.j = std::min(static_cast<int>(tj), nlat - 2);
  st.wj = tj - st.j;
  if (period > 0) {
    double ti = std::fmod((lon_deg - lon0) / dlon, static_cast<double>(period));
    if (ti < 0) ti += period;
    st.i0 = std::min(static_cast<int>(ti), period - 1);
    st.wi = ti - st.i0;
    st.i1 = st.i0 + 1 == period ? 0 : st.i0 + 1;
  } else {
    const double ti = std::clamp(column_of(lon_deg), 0.0, static_cast<double>(nlon - 1));
    st.i0 = std::min(static_cast<int>(ti), nlon - 2);
    st.wi = ti - st.i0;
    st.i1 = st.i0 + 1;
  }
  return st;
}

double LonLatGrid::column_of(double lon_deg) const {
  if (period > 0) return (lon_deg - lon0) / dlon;
  // The copy of lon_deg (mod 360) nearest to the grid's middle.
  const double mid = lon0 + 0.5 * dlon * (nlon - 1);
  const double l = lon_deg - 360 * std::round((lon_deg - mid) / 360);
  return (l - lon0) / dlon;
}

double LonLatGrid::interp(double lon_deg, double lat_deg) const {
  const Stencil st = stencil(lon_deg, lat_deg);
  const double a = at(st.i0, st.j) * (1 - st.wi) + at(st.i1, st.j) * st.wi;
  const double b = at(st.i0, st.j + 1) * (1 - st.wi) + at(st.i1, st.j + 1) * st.wi;
  return a * (1 - st.wj) + b * st.wj;
}

bool LonLatGrid::covers(double lon_deg, double lat_deg) const {
  const double tj = (lat_deg - lat0) / dlat;
  if (!(tj >= 0 && tj <= nlat - 1)) return false;
  if (period > 0) return true;
  const double ti = column_of(lon_deg);
  return ti >= 0 && ti <= nlon - 1;
}

void lonlat_of(const Vec3& p, double radius, double& lon_deg, double& lat_deg) {
  const double r = radius > 0 ? radius : norm(p);
  lon_deg = std::atan2(p.y, p.x) / kDeg;
  lat_deg = r > 0 ? std::asin(std::clamp(p.z / r, -1.0, 1.0)) / kDeg : 0.0;
}

Vec3 point_of(double lon_deg, double lat_deg, double radius) {
  const double lo = lon_deg * kDeg, la = lat_deg * kDeg;
  return {radius * std::cos(la) * std::cos(lo), radius * std::cos(la) * std::sin(lo),
          radius * std::sin(la)};
}

namespace {

class NcFile {
 public:
  explicit NcFile(const std::filesystem::path& file) : file_(file) {
    const int st = nc_open(file.c_str(), NC_NOWRITE, &id_);
    base::note_input_file(file.string());
    if (st != NC_NOERR) file_error(file, fmt::format("cannot open as netCDF: {}", nc_strerror(st)));
  }
  ~NcFile() { nc_close(id_); }
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;

  int id() const { return id_; }
  void check(int st, const std::string& what) const {
    if (st != NC_NOERR) file_error(file_, fmt::format("{}: {}", what, nc_strerror(st)));
  }
  int var(const std::string& name) const {
    int v;
    if (nc_inq_varid(id_, name.c_str(), &v) != NC_NOERR) {
      std::string names;
      int nv = 0;
      nc_inq_nvars(id_, &nv);
      for (int k = 0; k < nv; ++k) {
        char buf[NC_MAX_NAME + 1];
        nc_inq_varname(id_, k, buf);
        names += (names.empty() ? "" : ", ") + std::string(buf);
      }
      file_error(file_, fmt::format("no variable '{}' (variables: {})", name, names));
    }
    return v;
  }
  std::string var_name(int v) const {
    char buf[NC_MAX_NAME + 1];
    check(nc_inq_varname(id_, v, buf), "variable name");
    return buf;
  }
  std::vector<int> dims(int v) const {
    int nd = 0;
    check(nc_inq_varndims(id_, v, &nd), "variable dimensions");
    std::vector<int> d(static_cast<std::size_t>(nd));
    check(nc_inq_vardimid(id_, v, d.data()), "variable dimensions");
    return d;
  }
  std::size_t dim_len(int d) const {
    std::size_t n;
    check(nc_inq_dimlen(id_, d, &n), "dimension length");
    return n;
  }
  std::vector<double> read(int v, std::size_t n) const {
    std::vector<double> out(n);
    check(nc_get_var_double(id_, v, out.data()), fmt::format("reading '{}'", var_name(v)));
    return out;
  }
  /// The hyperslab start[k] .. start[k] + count[k] - 1 of a 2D variable.
  std::vector<double> read(int v, const std::size_t start[2], const std::size_t count[2]) const {
    std::vector<double> out(count[0] * count[1]);
    check(nc_get_vara_double(id_, v, start, count, out.data()), fmt::format("reading '{}'", var_name(v)));
    return out;
  }
  bool att(int v, const char* name, double& value) const {
    nc_type t;
    std::size_t len;
    if (nc_inq_att(id_, v, name, &t, &len) != NC_NOERR || len != 1 || t == NC_CHAR) return false;
    return nc_get_att_double(id_, v, name, &value) == NC_NOERR;
  }
  std::string text_att(int v, const char* name) const {
    nc_type t;
    std::size_t len;
    if (nc_inq_att(id_, v, name, &t, &len) != NC_NOERR || t != NC_CHAR) return "";
    std::string s(len, '\0');
    nc_get_att_text(id_, v, name, s.data());
    return s;
  }
  /// The coordinate variable of dimension d (same name), or -1.
  int coord_var(int d) const {
    char buf[NC_MAX_NAME + 1];
    check(nc_inq_dimname(id_, d, buf), "dimension name");
    int v;
    if (nc_inq_varid(id_, buf, &v) != NC_NOERR) return -1;
    const auto vd = dims(v);
    return vd.size() == 1 && vd[0] == d ? v : -1;
  }

 private:
  std::filesystem::path file_;
  int id_ = -1;
};

std::size_t type_size(nc_type t) {
  switch (t) {
    case NC_BYTE: case NC_CHAR: case NC_UBYTE: return 1;
    case NC_SHORT: case NC_USHORT: return 2;
    case NC_INT: case NC_FLOAT: case NC_UINT: return 4;
    case NC_DOUBLE: case NC_INT64: case NC_UINT64: return 8;
    default: return 0;
  }
}

std::uint64_t pad4(std::uint64_t n) { return (n + 3) / 4 * 4; }

// a * b, saturating (hostile headers announce sizes near 2^64).
std::uint64_t mul_sat(std::uint64_t a, std::uint64_t b) {
  return a != 0 && b > UINT64_MAX / a ? UINT64_MAX : a * b;
}
std::uint64_t add_sat(std::uint64_t a, std::uint64_t b) { return b > UINT64_MAX - a ? UINT64_MAX : a + b; }

// Lower bound of the bytes one attribute list takes in a classic header: tag,
// count, then per attribute its name, type, count and values padded to 4.
std::uint64_t classic_atts_bytes(int ncid, int v, int natts, std::uint64_t w) {
  std::uint64_t n = 4 + w;
  for (int a = 0; a < natts; ++a) {
    char name[NC_MAX_NAME + 1];
    nc_type t;
    std::size_t len = 0;
    if (nc_inq_attname(ncid, v, a, name) != NC_NOERR || nc_inq_att(ncid, v, name, &t, &len) != NC_NOERR) continue;
    n = add_sat(n, w + pad4(std::strlen(name)) + 4 + w + pad4(mul_sat(len, type_size(t))));
  }
  return n;
}

// In a classic (CDF-1/2/5) file the data of variable `zv` lies at or after the
// header and every fixed-size variable defined before it; libnetcdf reads the
// bytes a truncated file lacks as zeros, so the length is checked here. The
// header is serialised without its optional padding and the data unpadded,
// which makes the result a lower bound of the bytes the variable needs.
std::uint64_t classic_bytes_needed(int ncid, int format, int zv) {
  const std::uint64_t w = format == NC_FORMAT_CDF5 ? 8 : 4;   // counts and lengths
  const std::uint64_t dimid_w = format == NC_FORMAT_CDF5 ? 8 : 4;
  const std::uint64_t begin_w = format == NC_FORMAT_CLASSIC ? 4 : 8;
  int ndims = 0, nvars = 0, ngatts = 0, unlim = -1;
  if (nc_inq(ncid, &ndims, &nvars, &ngatts, &unlim) != NC_NOERR) return 0;
  std::uint64_t header = 4 + w + 4 + w;   // magic, numrecs, dimension list tag and count
  for (int d = 0; d < ndims; ++d) {
    char name[NC_MAX_NAME + 1];
    if (nc_inq_dimname(ncid, d, name) == NC_NOERR) header = add_sat(header, w + pad4(std::strlen(name)) + w);
  }
  header = add_sat(header, classic_atts_bytes(ncid, NC_GLOBAL, ngatts, w));
  header = add_sat(header, 4 + w);
  std::size_t nrecs = 0;
  if (unlim >= 0) nc_inq_dimlen(ncid, unlim, &nrecs);
  std::vector<std::uint64_t> data(static_cast<std::size_t>(nvars), 0);
  std::vector<bool> is_record(static_cast<std::size_t>(nvars), false);
  for (int v = 0; v < nvars; ++v) {
    char name[NC_MAX_NAME + 1];
    nc_type t;
    int nd = 0, natts = 0;
    int dimids[NC_MAX_VAR_DIMS];
    if (nc_inq_var(ncid, v, name, &t, &nd, dimids, &natts) != NC_NOERR) continue;
    header = add_sat(header, w + pad4(std::strlen(name)) + w + dimid_w * static_cast<std::uint64_t>(nd));
    header = add_sat(header, classic_atts_bytes(ncid, v, natts, w));
    header = add_sat(header, 4 + w + begin_w);
    std::uint64_t n = type_size(t);
    for (int k = 0; k < nd; ++k) {
      std::size_t len = 0;
      nc_inq_dimlen(ncid, dimids[k], &len);
      if (dimids[k] == unlim) is_record[static_cast<std::size_t>(v)] = true;
      n = mul_sat(n, len);
    }
    data[static_cast<std::size_t>(v)] = n;
  }
  // Fixed-size variables come first, in definition order; record variables after all of them.
  std::uint64_t end = header;
  for (int v = 0; v < nvars; ++v) {
    if (is_record[static_cast<std::size_t>(v)]) continue;
    end = add_sat(end, data[static_cast<std::size_t>(v)]);
    if (v == zv) return end;
  }
  for (int v = 0; v < nvars; ++v)
    if (is_record[static_cast<std::size_t>(v)]) end = add_sat(end, data[static_cast<std::size_t>(v)]);
  return end;
}

bool looks_like_lon(const NcFile& nc, int v) {
  const std::string u = nc.text_att(v, "units");
  if (u.find("east") != std::string::npos) return true;
  std::string n = nc.var_name(v);
  std::transform(n.begin(), n.end(), n.begin(), ::tolower);
  return n.find("lon") != std::string::npos || n == "x" || n.back() == 'x';
}

}  // namespace

LonLatGrid read_netcdf_grid(const std::filesystem::path& file, const NetcdfGridSpec& spec, GridAttributes* attrs) {
  if (!std::filesystem::exists(file)) file_error(file, "no such file");
  // nc_open allocates what the header declares before it checks the file's length.
  if (auto why = check_netcdf_header_counts(file)) file_error(file, *why);
  // libnetcdf is not thread-safe (base/netcdf_lock.h): every call into it here is in this
  // function, held from open to close; reads happen when a field is built, never while one
  // is evaluated.
  const std::lock_guard<std::mutex> lock(base::netcdf_lock());
  NcFile nc(file);
  int zv = -1;
  if (!spec.z_var.empty()) {
    zv = nc.var(spec.z_var);
  } else {
    int nv = 0;
    nc.check(nc_inq_nvars(nc.id(), &nv), "listing variables");
    for (int k = 0; k < nv && zv < 0; ++k)
      if (nc.dims(k).size() == 2) zv = k;
    if (zv < 0) file_error(file, "no 2D variable to read (set the value variable name)");
  }
  const std::string zname = nc.var_name(zv);
  const auto zd = nc.dims(zv);
  if (zd.size() != 2)
    file_error(file, fmt::format("variable '{}' has {} dimensions, a 2D (lat, lon) grid is needed",
                                 zname, zd.size()));
  // Which dimension of z is longitude: from the named variables, else from
  // the coordinate variables' units/names.
  int lon_v = spec.lon_var.empty() ? -1 : nc.var(spec.lon_var);
  int lat_v = spec.lat_var.empty() ? -1 : nc.var(spec.lat_var);
  int lon_axis = -1;  // 0 or 1: position of the lon dimension in z
  for (int a = 0; a < 2; ++a) {
    const int cv = nc.coord_var(zd[static_cast<std::size_t>(a)]);
    if (lon_v >= 0 && nc.dims(lon_v) == std::vector<int>{zd[static_cast<std::size_t>(a)]}) lon_axis = a;
    if (lat_v >= 0 && nc.dims(lat_v) == std::vector<int>{zd[static_cast<std::size_t>(a)]}) lon_axis = 1 - a;
    if (lon_v < 0 && lat_v < 0 && cv >= 0 && looks_like_lon(nc, cv)) lon_axis = a;
  }
  if (lon_axis < 0) lon_axis = 1;  // CF's usual z(lat, lon)
  const int lon_dim = zd[static_cast<std::size_t>(lon_axis)];
  const int lat_dim = zd[static_cast<std::size_t>(1 - lon_axis)];
  if (lon_v < 0) lon_v = nc.coord_var(lon_dim);
  if (lat_v < 0) lat_v = nc.coord_var(lat_dim);
  if (lon_v < 0 || lat_v < 0)
    file_error(file, fmt::format("cannot find the longitude/latitude coordinates of '{}' (set the "
                                 "variable names)", zname));
  if (nc.dims(lon_v) != std::vector<int>{lon_dim} || nc.dims(lat_v) != std::vector<int>{lat_dim})
    file_error(file, fmt::format("'{}' and '{}' are not the 1D coordinates of the dimensions of '{}'",
                                 nc.var_name(lon_v), nc.var_name(lat_v), zname));
  const std::size_t nx = nc.dim_len(lon_dim), ny = nc.dim_len(lat_dim);
  // Sizes are checked before anything is allocated: against the file length for
  // the classic formats, against a fixed bound for netCDF-4 (whose compressed
  // data may be far smaller than the grid; its reads fail on a cut file).
  const bool windowed = !spec.window.empty();
  if (nx < 2 || ny < 2 || nx > kMaxGridSide || ny > kMaxGridSide || (!windowed && mul_sat(nx, ny) > kMaxGridValues))
    file_error(file, fmt::format("variable '{}' is a {} x {} grid: each side must be 2 to {} and the grid at "
                                 "most {} values", zname, ny, nx, kMaxGridSide, kMaxGridValues));
  int format = 0;
  nc.check(nc_inq_format(nc.id(), &format), "file format");
  if (format == NC_FORMAT_CLASSIC || format == NC_FORMAT_64BIT_OFFSET || format == NC_FORMAT_CDF5) {
    std::error_code ec;
    const std::uintmax_t have = std::filesystem::file_size(file, ec);
    const std::uint64_t need = classic_bytes_needed(nc.id(), format, zv);
    if (!ec && need > have)
      file_error(file, fmt::format("variable '{}' needs at least {} bytes but the file has {}: the file is "
                                   "truncated", zname, need, have));
    for (int cv : {lon_v, lat_v}) {
      const std::uint64_t need_c = classic_bytes_needed(nc.id(), format, cv);
      if (!ec && need_c > have)
        file_error(file, fmt::format("variable '{}' needs at least {} bytes but the file has {}: the file is "
                                     "truncated", nc.var_name(cv), need_c, have));
    }
  }
  const auto [x0, dx] = even_axis(file, "longitude", nc.var_name(lon_v), nc.read(lon_v, nx));
  const auto [y0, dy] = even_axis(file, "latitude", nc.var_name(lat_v), nc.read(lat_v, ny));
  double scale = 1, offset = 0, fill = 0, missing = 0;
  const bool has_scale = nc.att(zv, "scale_factor", scale);
  const bool has_offset = nc.att(zv, "add_offset", offset);
  const bool has_fill = nc.att(zv, "_FillValue", fill);
  const bool has_missing = nc.att(zv, "missing_value", missing);
  if (has_scale && !(std::isfinite(scale) && scale != 0))
    file_error(file, fmt::format("variable '{}': scale_factor {} must be finite and non-zero", zname, scale));
  if (has_offset && !std::isfinite(offset))
    file_error(file, fmt::format("variable '{}': add_offset {} must be finite", zname, offset));
  // The columns c0 .. c0 + cn - 1 and rows r0 .. r0 + rn - 1 (file order) to read.
  std::size_t c0 = 0, cn = nx, r0 = 0, rn = ny;
  if (windowed) window_of(file, spec.window, x0, dx, nx, y0, dy, ny, c0, cn, r0, rn);
  if (windowed && mul_sat(cn, rn) > kMaxGridValues)
    file_error(file, fmt::format("variable '{}': the window's {} x {} nodes are more than {}", zname, rn, cn,
                                 kMaxGridValues));
  std::vector<double> raw;
  if (windowed) {
    const std::size_t start[2] = {lon_axis == 1 ? r0 : c0, lon_axis == 1 ? c0 : r0};
    const std::size_t count[2] = {lon_axis == 1 ? rn : cn, lon_axis == 1 ? cn : rn};
    raw = nc.read(zv, start, count);
  } else {
    raw = nc.read(zv, nx * ny);
  }
  // The first column and row read (equal to x0, y0 without a window).
  const double wx0 = c0 ? x0 + dx * static_cast<double>(c0) : x0;
  const double wy0 = r0 ? y0 + dy * static_cast<double>(r0) : y0;

  LonLatGrid g;
  g.nlon = static_cast<int>(cn);
  g.nlat = static_cast<int>(rn);
  g.dlon = std::fabs(dx);
  g.dlat = std::fabs(dy);
  g.lon0 = dx > 0 ? wx0 : wx0 + dx * static_cast<double>(cn - 1);
  g.lat0 = dy > 0 ? wy0 : wy0 + dy * static_cast<double>(rn - 1);
  check_extent(file, g);
  g.v.resize(cn * rn);
  for (std::size_t r = 0; r < rn; ++r)
    for (std::size_t c = 0; c < cn; ++c) {
      const double raw_v = lon_axis == 1 ? raw[r * cn + c] : raw[c * rn + r];
      double val = raw_v;
      if ((has_fill && raw_v == fill) || (has_missing && raw_v == missing) || std::isnan(raw_v)) {
        val = std::nan("");
      } else {
        if (has_scale) val *= scale;
        if (has_offset) val += offset;
      }
      const std::size_t i = dx > 0 ? c : cn - 1 - c;
      const std::size_t j = dy > 0 ? r : rn - 1 - r;
      if (std::isinf(val))
        file_error(file, fmt::format("variable '{}': value {} at lon {}, lat {} is not finite (raw {}, "
                                     "scale_factor {}, add_offset {})", zname, val,
                                     wx0 + dx * static_cast<double>(c), wy0 + dy * static_cast<double>(r),
                                     raw_v, scale, offset));
      g.v[j * cn + i] = val;
    }
  g.detect_wrap();
  if (attrs) {
    attrs->units = nc.text_att(zv, "units");
    attrs->crs.clear();
    // CF: the variable's grid_mapping attribute names a variable whose attributes
    // describe the reference system; the fullest description it carries is kept.
    const std::string mapping = nc.text_att(zv, "grid_mapping");
    int mv = -1;
    if (!mapping.empty() && nc_inq_varid(nc.id(), mapping.c_str(), &mv) == NC_NOERR)
      for (const char* key : {"crs_wkt", "spatial_ref", "epsg_code", "grid_mapping_name"})
        if (attrs->crs.empty()) attrs->crs = nc.text_att(mv, key);
  }
  return g;
}

namespace {

// Whitespace-separated words of an ESRI ASCII grid, each with its line number.
class AscWords {
 public:
  explicit AscWords(std::string_view text) : s_(text) {}
  /// The next word, empty at the end of the text; `line` is where it starts.
  std::string_view next(int& line) {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const std::size_t b = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    line = line_;
    return s_.substr(b, pos_ - b);
  }
  std::string_view peek() const {
    std::size_t p = pos_;
    while (p < s_.size() && std::isspace(static_cast<unsigned char>(s_[p]))) ++p;
    std::size_t e = p;
    while (e < s_.size() && !std::isspace(static_cast<unsigned char>(s_[e]))) ++e;
    return s_.substr(p, e - p);
  }
  std::size_t remaining() const { return s_.size() - pos_; }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

// The whole word as a finite number.
bool finite_number(std::string_view w, double& v) {
  if (!w.empty() && w.front() == '+') w.remove_prefix(1);
  const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
  return r.ec == std::errc{} && r.ptr == w.data() + w.size() && std::isfinite(v);
}

std::string shown(std::string_view w) { return std::string(w.substr(0, 40)); }

}  // namespace

LonLatGrid parse_esri_ascii_grid(std::string_view text, const std::filesystem::path& file) {
  long ncols = -1, nrows = -1;
  double x = NAN, y = NAN, cell = NAN, nodata = NAN;
  bool x_center = false, y_center = false, has_nodata = false;
  int line = 1;
  AscWords words(text);
  // Header keys in any order and case, until the first word that is not a name.
  for (std::string_view w = words.peek(); !w.empty() && std::isalpha(static_cast<unsigned char>(w.front()));
       w = words.peek()) {
    std::string key(words.next(line));
    std::transform(key.begin(), key.end(), key.begin(), ::tolower);
    int vline = line;
    const std::string_view vw = words.next(vline);
    double val;
    if (vw.empty() || vline != line || !finite_number(vw, val))
      file_error(file, fmt::format("line {}: header '{}' needs a finite number, not '{}'", line, shown(key),
                                   vline == line ? shown(vw) : std::string()));
    auto size = [&](long& out) {
      // Sizes are checked before anything is allocated: a hostile header must not
      // ask for terabytes.
      if (!(val >= 2 && val <= 2147483647.0 && val == std::floor(val)))
        file_error(file, fmt::format("line {}: {} {} must be a whole number from 2 to 2147483647", line, key,
                                     shown(vw)));
      out = static_cast<long>(val);
    };
    const bool seen = (key == "ncols" && ncols >= 0) || (key == "nrows" && nrows >= 0) ||
                      ((key == "xllcorner" || key == "xllcenter") && !std::isnan(x)) ||
                      ((key == "yllcorner" || key == "yllcenter") && !std::isnan(y)) ||
                      (key == "cellsize" && !std::isnan(cell)) || (key == "nodata_value" && has_nodata);
    if (seen) file_error(file, fmt::format("line {}: header '{}' given twice", line, key));
    if (key == "ncols") size(ncols);
    else if (key == "nrows") size(nrows);
    else if (key == "xllcorner") x = val;
    else if (key == "xllcenter") x = val, x_center = true;
    else if (key == "yllcorner") y = val;
    else if (key == "yllcenter") y = val, y_center = true;
    else if (key == "cellsize") {
      if (!(val > 0)) file_error(file, fmt::format("line {}: cellsize {} must be positive", line, shown(vw)));
      cell = val;
    } else if (key == "nodata_value") nodata = val, has_nodata = true;
    else file_error(file, fmt::format("line {}: unknown header '{}'", line, shown(key)));
  }
  if (ncols < 0 || nrows < 0 || std::isnan(x) || std::isnan(y) || std::isnan(cell))
    file_error(file, "incomplete header (need ncols, nrows >= 2, xll*, yll*, cellsize > 0)");
  // Every value takes at least one character and one separator (the last one may
  // lack its separator).
  const auto values = static_cast<unsigned long long>(ncols) * static_cast<unsigned long long>(nrows);
  if (values > (words.remaining() + 1) / 2)
    file_error(file, fmt::format("the header announces {} x {} values but only {} bytes of data follow "
                                 "(truncated file or wrong header)", nrows, ncols, words.remaining()));
  LonLatGrid g;
  g.nlon = static_cast<int>(ncols);
  g.nlat = static_cast<int>(nrows);
  g.dlon = g.dlat = cell;
  // Corner registration: node values stand for cell centres.
  g.lon0 = x_center ? x : x + cell / 2;
  g.lat0 = y_center ? y : y + cell / 2;
  check_extent(file, g);
  g.v.resize(static_cast<std::size_t>(values));
  for (long r = 0; r < nrows; ++r)
    for (long c = 0; c < ncols; ++c) {
      const std::string_view w = words.next(line);
      double val;
      if (w.empty())
        file_error(file, fmt::format("data ends early: row {} column {} of {} x {}", r + 1, c + 1,
                                     nrows, ncols));
      if (!finite_number(w, val))
        file_error(file, fmt::format("line {}: row {} column {}: '{}' is not a finite number", line, r + 1,
                                     c + 1, shown(w)));
      if (has_nodata && val == nodata) val = std::nan("");
      g.at(static_cast<int>(c), static_cast<int>(nrows - 1 - r)) = val;  // first row = north
    }
  if (!words.next(line).empty()) file_error(file, fmt::format("line {}: more values than ncols x nrows", line));
  g.detect_wrap();
  return g;
}

LonLatGrid read_esri_ascii_grid(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) file_error(file, std::filesystem::exists(file) ? "cannot be read" : "no such file");
  base::note_input_file(file.string());
  std::ostringstream all;
  all << in.rdbuf();
  if (in.bad()) file_error(file, "read error");
  const std::string text = std::move(all).str();
  return parse_esri_ascii_grid(text, file);
}

}  // namespace sm::field
