// Lon/lat grid readers (netCDF through libnetcdf, ESRI ASCII by hand) and
// bilinear interpolation.
#include "field/lonlat_grid.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <mutex>
#include <numbers>
#include <sstream>

#include <fmt/format.h>
#include <netcdf.h>

#include "field/error.h"

namespace sm::field {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

[[noreturn]] void file_error(const std::filesystem::path& file, const std::string& what) {
  FieldError e(FieldErrc::FileError, fmt::format("{}: {}", file.string(), what));
  e.file = file.string();
  throw e;
}

/// Checks that `c` is evenly spaced; returns (first, step), step may be < 0.
std::pair<double, double> even_axis(const std::filesystem::path& file, const std::string& name,
                                    const std::vector<double>& c) {
  if (c.size() < 2) file_error(file, fmt::format("coordinate '{}' needs at least 2 values", name));
  const double step = (c.back() - c.front()) / static_cast<double>(c.size() - 1);
  if (!(std::fabs(step) > 0) || !std::isfinite(step))
    file_error(file, fmt::format("coordinate '{}' is not monotonic", name));
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double expect = c.front() + step * static_cast<double>(k);
    if (std::fabs(c[k] - expect) > 1e-3 * std::fabs(step))
      file_error(file, fmt::format("coordinate '{}' is not evenly spaced (value {} at index {}, "
                                   "expected {})", name, c[k], k, expect));
  }
  return {c.front(), step};
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

double LonLatGrid::interp(double lon_deg, double lat_deg) const {
  double tj = std::clamp((lat_deg - lat0) / dlat, 0.0, static_cast<double>(nlat - 1));
  int j = std::min(static_cast<int>(tj), nlat - 2);
  const double wj = tj - j;
  int i0, i1;
  double wi;
  if (period > 0) {
    double ti = std::fmod((lon_deg - lon0) / dlon, static_cast<double>(period));
    if (ti < 0) ti += period;
    i0 = std::min(static_cast<int>(ti), period - 1);
    wi = ti - i0;
    i1 = i0 + 1 == period ? 0 : i0 + 1;
  } else {
    // The copy of lon_deg (mod 360) nearest to the grid's middle.
    const double mid = lon0 + 0.5 * dlon * (nlon - 1);
    const double l = lon_deg - 360 * std::round((lon_deg - mid) / 360);
    const double ti = std::clamp((l - lon0) / dlon, 0.0, static_cast<double>(nlon - 1));
    i0 = std::min(static_cast<int>(ti), nlon - 2);
    wi = ti - i0;
    i1 = i0 + 1;
  }
  const double a = at(i0, j) * (1 - wi) + at(i1, j) * wi;
  const double b = at(i0, j + 1) * (1 - wi) + at(i1, j + 1) * wi;
  return a * (1 - wj) + b * wj;
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

bool looks_like_lon(const NcFile& nc, int v) {
  const std::string u = nc.text_att(v, "units");
  if (u.find("east") != std::string::npos) return true;
  std::string n = nc.var_name(v);
  std::transform(n.begin(), n.end(), n.begin(), ::tolower);
  return n.find("lon") != std::string::npos || n == "x" || n.back() == 'x';
}

}  // namespace

LonLatGrid read_netcdf_grid(const std::filesystem::path& file, const NetcdfGridSpec& spec) {
  if (!std::filesystem::exists(file)) file_error(file, "no such file");
  // libnetcdf is not thread-safe: its table of open files is shared, and two reads at once
  // fail ("Not a valid ID") or crash. Every call into it is in this function, so one lock
  // held from open to close makes reads from several threads safe; reads happen when a
  // field is built, never while one is evaluated.
  static std::mutex netcdf_lock;
  const std::lock_guard<std::mutex> lock(netcdf_lock);
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
  const auto [x0, dx] = even_axis(file, nc.var_name(lon_v), nc.read(lon_v, nx));
  const auto [y0, dy] = even_axis(file, nc.var_name(lat_v), nc.read(lat_v, ny));
  std::vector<double> raw = nc.read(zv, nx * ny);
  double scale = 1, offset = 0, fill = 0, missing = 0;
  const bool has_scale = nc.att(zv, "scale_factor", scale);
  const bool has_offset = nc.att(zv, "add_offset", offset);
  const bool has_fill = nc.att(zv, "_FillValue", fill);
  const bool has_missing = nc.att(zv, "missing_value", missing);

  LonLatGrid g;
  g.nlon = static_cast<int>(nx);
  g.nlat = static_cast<int>(ny);
  g.dlon = std::fabs(dx);
  g.dlat = std::fabs(dy);
  g.lon0 = dx > 0 ? x0 : x0 + dx * static_cast<double>(nx - 1);
  g.lat0 = dy > 0 ? y0 : y0 + dy * static_cast<double>(ny - 1);
  g.v.resize(nx * ny);
  for (std::size_t r = 0; r < ny; ++r)
    for (std::size_t c = 0; c < nx; ++c) {
      const double raw_v = lon_axis == 1 ? raw[r * nx + c] : raw[c * ny + r];
      double val = raw_v;
      if ((has_fill && raw_v == fill) || (has_missing && raw_v == missing) || std::isnan(raw_v)) {
        val = std::nan("");
      } else {
        if (has_scale) val *= scale;
        if (has_offset) val += offset;
      }
      const std::size_t i = dx > 0 ? c : nx - 1 - c;
      const std::size_t j = dy > 0 ? r : ny - 1 - r;
      g.v[j * nx + i] = val;
    }
  g.detect_wrap();
  return g;
}

LonLatGrid read_esri_ascii_grid(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) file_error(file, std::filesystem::exists(file) ? "cannot be read" : "no such file");
  long ncols = -1, nrows = -1;
  double x = NAN, y = NAN, cell = NAN, nodata = NAN;
  bool x_center = false, y_center = false, has_nodata = false;
  std::string key;
  // Header keys in any order and case, until the first number.
  while (in >> std::ws && in.peek() != EOF &&
         !(std::isdigit(in.peek()) || in.peek() == '-' || in.peek() == '+' || in.peek() == '.')) {
    in >> key;
    std::transform(key.begin(), key.end(), key.begin(), ::tolower);
    double val;
    if (!(in >> val)) file_error(file, fmt::format("header '{}' has no numeric value", key));
    if (key == "ncols") ncols = static_cast<long>(val);
    else if (key == "nrows") nrows = static_cast<long>(val);
    else if (key == "xllcorner") x = val;
    else if (key == "xllcenter") x = val, x_center = true;
    else if (key == "yllcorner") y = val;
    else if (key == "yllcenter") y = val, y_center = true;
    else if (key == "cellsize") cell = val;
    else if (key == "nodata_value") nodata = val, has_nodata = true;
    else file_error(file, fmt::format("unknown header '{}'", key));
  }
  if (ncols < 2 || nrows < 2 || std::isnan(x) || std::isnan(y) || !(cell > 0))
    file_error(file, "incomplete header (need ncols, nrows >= 2, xll*, yll*, cellsize > 0)");
  LonLatGrid g;
  g.nlon = static_cast<int>(ncols);
  g.nlat = static_cast<int>(nrows);
  g.dlon = g.dlat = cell;
  // Corner registration: node values stand for cell centres.
  g.lon0 = x_center ? x : x + cell / 2;
  g.lat0 = y_center ? y : y + cell / 2;
  g.v.resize(static_cast<std::size_t>(ncols * nrows));
  for (long r = 0; r < nrows; ++r)
    for (long c = 0; c < ncols; ++c) {
      double val;
      if (!(in >> val))
        file_error(file, fmt::format("data ends early: row {} column {} of {} x {}", r + 1, c + 1,
                                     nrows, ncols));
      if (has_nodata && val == nodata) val = std::nan("");
      g.at(static_cast<int>(c), static_cast<int>(nrows - 1 - r)) = val;  // first row = north
    }
  double extra;
  if (in >> extra) file_error(file, "more values than ncols x nrows");
  g.detect_wrap();
  return g;
}

}  // namespace sm::field
