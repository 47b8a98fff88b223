// Bathymetry field: reads a netCDF or ESRI ASCII relief grid and gives, at
// the lon/lat of each 3D point, the depth H (clamped to MinDepth), the
// wavelength criterion f1 = lambda_min/N sqrt(H_ref/H) or the Hessian
// criterion f2 = 1/sqrt(|lambda_max|) of the paper's section 3.1.
#include "field/bathymetry.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "field/error.h"
#include "field/kinds.h"

namespace sm::field {

namespace {
constexpr double kMaxRelief = 1e6;   // metres
constexpr double kGravity = 9.81;    // m/s^2

// The centred differences the Hessian and slope criteria take on one grid, so that both
// see the depth the same way: neighbour columns wrapped on a global grid and one-sided
// (clamped) at the edges of a regional one; neighbour rows clamped; cos(lat) bounded
// below by the half-width of the polar row, where the longitude derivatives would blow
// up with 1/cos.
struct GridStencil {
  static constexpr double kDeg = std::numbers::pi / 180;
  explicit GridStencil(const LonLatGrid& grid)
      : g(grid), dl(grid.dlon * kDeg), dp(grid.dlat * kDeg) {}
  struct Row {
    int jm, jp;
    double sp;    // latitude span of the centred difference (radians)
    double phi;   // latitude (radians)
    double c;     // bounded cos(phi)
  };
  struct Column {
    int im, ip;
    double sl;    // longitude span of the centred difference (radians)
  };
  int col(int i) const { return g.period ? g.wrap(i) : std::clamp(i, 0, g.nlon - 1); }
  Row row(int j) const {
    const int jm = std::max(j - 1, 0), jp = std::min(j + 1, g.nlat - 1);
    const double phi = g.lat(j) * kDeg;
    return {jm, jp, (jp - jm) * dp, phi, std::max(std::cos(phi), std::sin(dp / 2))};
  }
  Column column(int i) const {
    const int im = col(i - 1), ip = col(i + 1);
    return {im, ip, (g.period ? 2 : ip - im) * dl};
  }

  const LonLatGrid& g;
  const double dl, dp;   // grid steps (radians)
};

}  // namespace

LonLatGrid hessian_criterion(const LonLatGrid& depth, double depth_ref, double radius) {
  const GridStencil st(depth);
  const double dl = st.dl, dp = st.dp;
  LonLatGrid out = depth;
  const int nx = depth.nlon, ny = depth.nlat;
  auto col = [&](int i) { return st.col(i); };
  for (int j = 0; j < ny; ++j) {
    const GridStencil::Row r = st.row(j);
    const int jm = r.jm, jp = r.jp;
    const double sp = r.sp, c = r.c;
    const double t = std::sin(r.phi) / c;
    for (int i = 0; i < nx; ++i) {
      const GridStencil::Column k = st.column(i);
      const int im = k.im, ip = k.ip;
      const double sl = k.sl;
      auto h = [&](int a, int b) { return depth.at(a, b) / depth_ref; };
      const double hl = (h(ip, j) - h(im, j)) / sl;
      const double hp = (h(i, jp) - h(i, jm)) / sp;
      // Second differences use the true neighbours when both exist, and are
      // taken from the nearest interior node at an edge.
      const int ic = depth.period ? i : std::clamp(i, 1, nx - 2);
      const int jc = std::clamp(j, 1, ny - 2);
      const double hll = (h(col(ic + 1), j) - 2 * h(ic, j) + h(col(ic - 1), j)) / (dl * dl);
      const double hpp = (h(i, jc + 1) - 2 * h(i, jc) + h(i, jc - 1)) / (dp * dp);
      const double hlp = (h(ip, jp) - h(ip, jm) - h(im, jp) + h(im, jm)) / (sl * sp);
      // Covariant Hessian in the orthonormal (east, north) frame, metres:
      // H_ee = (H_ll/cos^2 - tan H_p)/R^2, H_nn = H_pp/R^2,
      // H_en = (H_lp + tan H_l)/(R^2 cos).
      const double r2 = radius * radius;
      const double a = (hll / (c * c) - t * hp) / r2;
      const double b = hpp / r2;
      const double e = (hlp + t * hl) / (r2 * c);
      const double m = 0.5 * (a + b), d = std::sqrt(0.25 * (a - b) * (a - b) + e * e);
      const double lmax = std::max(std::fabs(m + d), std::fabs(m - d));
      out.at(i, j) = lmax > 0 ? std::min(1 / std::sqrt(lmax), kMaxLc) : kMaxLc;
    }
  }
  return out;
}

namespace {

enum class Output { Wavelength, Hessian, Tidal, Slope };

class BathymetryField final : public SizeField {
 public:
  BathymetryField(LonLatGrid grid, double radius, Output out, double scale)
      : grid_(std::move(grid)), radius_(radius), out_(out), scale_(scale) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double lon, lat;
      lonlat_of(pts[i], radius_, lon, lat);
      const double v = grid_.interp(lon, lat);
      // f1 is interpolated through H (not node-wise) so that it is exactly
      // lambda_min/N sqrt(H_ref/H) of the interpolated depth.
      // So is the tidal size: T sqrt(g H) / N of the interpolated depth.
      h[i] = out_ == Output::Wavelength ? scale_ / std::sqrt(v) : out_ == Output::Tidal ? scale_ * std::sqrt(v) : v;
    }
  }

 private:
  LonLatGrid grid_;
  double radius_;
  Output out_;
  double scale_;
};

}  // namespace

LonLatGrid slope_criterion(const LonLatGrid& depth, double n, double radius) {
  const GridStencil st(depth);
  LonLatGrid out = depth;
  const int nx = depth.nlon, ny = depth.nlat;
  for (int j = 0; j < ny; ++j) {
    const GridStencil::Row r = st.row(j);
    const int jm = r.jm, jp = r.jp;
    const double sp = r.sp, c = r.c;
    for (int i = 0; i < nx; ++i) {
      const GridStencil::Column k = st.column(i);
      const int im = k.im, ip = k.ip;
      const double sl = k.sl;
      // Gradient in the orthonormal (east, north) frame, metres per metre.
      const double ge = (depth.at(ip, j) - depth.at(im, j)) / (sl * radius * c);
      const double gn = (depth.at(i, jp) - depth.at(i, jm)) / (sp * radius);
      const double g = std::hypot(ge, gn);
      out.at(i, j) = g > 0 ? std::min(2 * std::numbers::pi / n * depth.at(i, j) / g, kMaxLc) : kMaxLc;
    }
  }
  return out;
}

namespace {

// The file names of FileName: one, or a comma-separated list by priority.
std::vector<std::string> file_names(const BuildInputs& in) {
  const std::string& all = in.opts.string("FileName");
  std::vector<std::string> names;
  std::size_t b = 0;
  for (std::size_t k = 0; k <= all.size(); ++k) {
    if (k < all.size() && all[k] != ',') continue;
    std::size_t lo = b, hi = k;
    while (lo < hi && std::isspace(static_cast<unsigned char>(all[lo]))) ++lo;
    while (hi > lo && std::isspace(static_cast<unsigned char>(all[hi - 1]))) --hi;
    names.push_back(all.substr(lo, hi - lo));
    b = k + 1;
  }
  if (names.size() == 1 && names[0].empty()) in.bad("FileName", "no bathymetry file given");
  for (const std::string& n : names)
    if (n.empty()) in.bad("FileName", fmt::format("empty name in the list '{}'", all));
  return names;
}

[[noreturn]] void grid_error(const BuildInputs& in, const std::filesystem::path& path, const std::string& what) {
  FieldError e(FieldErrc::FileError, fmt::format("{}: {}", path.string(), what));
  e.file = path.string();
  e.reason = what;
  e.field_id = in.id;
  throw e;
}

// One relief grid as positive depths (the sign of Positive applied), missing values
// kept as NaN, nothing clamped.
LonLatGrid read_raw_depth_grid(const BuildInputs& in, const std::string& file, GridAttributes& attrs) {
  const Options& o = in.opts;
  const auto path = in.path(file);
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  NetcdfGridSpec spec{o.string("LonVariable"), o.string("LatVariable"), o.string("ZVariable"), {}};
  if (o.find("Window") >= 0 && !o.list("Window").empty()) {
    const std::vector<double>& w = o.list("Window");
    if (w.size() != 4 || !(w[0] < w[1] && w[1] - w[0] <= 360 && w[2] < w[3]) ||
        !std::all_of(w.begin(), w.end(), [](double x) { return std::isfinite(x); }))
      in.bad("Window", "must be {W, E, S, N} in degrees with W < E (at most 360 apart) and S < N");
    spec.window = w;
  }
  LonLatGrid g;
  attrs = {};
  try {
    g = ext == ".asc" ? read_esri_ascii_grid(path) : read_netcdf_grid(path, spec, &attrs);
  } catch (FieldError& e) {
    e.field_id = in.id;
    e.option = "FileName";
    throw;
  }
  const std::string& positive = o.string("Positive");
  if (positive != "up" && positive != "down") in.bad("Positive", "must be \"up\" or \"down\"");
  const double min_depth = o.number("MinDepth");
  if (!std::isfinite(min_depth)) in.bad("MinDepth", "must be finite");
  const double sign = positive == "up" ? -1 : 1;
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i) {
      double& v = g.at(i, j);
      if (std::isnan(v)) continue;
      // The deepest trench is 11 km and the highest summit 9 km: a relief beyond
      // 1000 km is a unit or packing error (a scale_factor of 1e300, say).
      if (std::fabs(v) > kMaxRelief)
        grid_error(in, path, fmt::format("relief {} m at lon {}, lat {} is not an Earth depth or height in metres "
                                         "(check the file's scale_factor, add_offset and units)",
                                         v, g.lon(i), g.lat(j)));
      v = sign * v;
    }
  return g;
}

// Refuses missing values unless MissingAsLand: the grid that has the last word must
// give a depth everywhere.
void check_no_missing(const BuildInputs& in, const std::string& file, const LonLatGrid& g) {
  if (in.opts.number("MissingAsLand") != 0) return;
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i)
      if (std::isnan(g.at(i, j)))
        grid_error(in, in.path(file),
                   fmt::format("missing or NaN value at lon {}, lat {} (set MissingAsLand = 1 to treat missing nodes "
                               "as land)", g.lon(i), g.lat(j)));
}

}  // namespace

LonLatGrid read_depth_grid(const BuildInputs& in) {
  const std::vector<std::string> files = file_names(in);
  if (files.size() > 1)
    in.bad("FileName", "one grid here: a list of grids by priority is read by Bathymetry with Output \"depth\"");
  GridAttributes attrs;
  LonLatGrid g = read_raw_depth_grid(in, files[0], attrs);
  check_no_missing(in, files[0], g);
  const double min_depth = in.opts.number("MinDepth");
  for (double& v : g.v) v = std::isnan(v) ? min_depth : std::max(v, min_depth);
  return g;
}

namespace {

// Units as one word, so that "metres" and "m" agree.
std::string unit_word(std::string u) {
  while (!u.empty() && (u.back() == '\0' || std::isspace(static_cast<unsigned char>(u.back())))) u.pop_back();
  std::size_t b = 0;
  while (b < u.size() && std::isspace(static_cast<unsigned char>(u[b]))) ++b;
  u = u.substr(b);
  std::transform(u.begin(), u.end(), u.begin(), ::tolower);
  for (const char* m : {"m", "meter", "meters", "metre", "metres"})
    if (u == m) return "m";
  for (const char* km : {"km", "kilometer", "kilometers", "kilometre", "kilometres"})
    if (u == km) return "km";
  return u;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back())))) s.pop_back();
  return s;
}

constexpr double kDegree = std::numbers::pi / 180;

// Angle (radians) between two points given in degrees, by the haversine formula
// (accurate for the small angles of a cell's neighbourhood).
double angle_between(double lon1, double lat1, double lon2, double lat2) {
  const double sp = std::sin(0.5 * (lat2 - lat1) * kDegree), sl = std::sin(0.5 * (lon2 - lon1) * kDegree);
  const double a = sp * sp + std::cos(lat1 * kDegree) * std::cos(lat2 * kDegree) * sl * sl;
  return 2 * std::asin(std::min(1.0, std::sqrt(a)));
}

// Depths from relief grids by priority. Grids hold positive depths with NaN where a
// value is missing; MinDepth is applied to what a point reads, so that the clamp is
// counted. Every grid but the last answers only within its nodes and where its
// values are present; the last answers everywhere (its edge value outside, missing
// values as MinDepth: MissingAsLand, checked when it was read).
class DepthGridsField final : public GridDepthField {
 public:
  DepthGridsField(std::vector<LonLatGrid> grids, double radius, double min_depth)
      : grids_(std::move(grids)), radius_(radius), min_depth_(min_depth) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    node_depths(pts, {}, h, nullptr);
  }

  void node_depths(std::span<const Vec3> pts, std::span<const double> half_size, std::span<double> out,
                   DepthClampReport* report) const override {
    DepthClampReport rep;
    rep.min_depth = min_depth_;
    rep.points = pts.size();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double lon, lat;
      lonlat_of(pts[i], radius_, lon, lat);
      Sample s;
      for (std::size_t k = 0; k < grids_.size(); ++k) {
        const bool last = k + 1 == grids_.size();
        if (half_size.empty() ? bilinear(grids_[k], last, lon, lat, s)
                              : cell_mean(grids_[k], last, lon, lat, half_size[i], s))
          break;
      }
      out[i] = s.value;
      if (s.value > s.grid) {
        ++rep.clamped;
        if (s.grid <= 0) ++rep.dry;
        if (!rep.has_worst || s.value - s.grid > rep.value - rep.grid_depth) {
          rep.has_worst = true;
          rep.lon = lon, rep.lat = lat, rep.grid_depth = s.grid, rep.value = s.value;
        }
      }
    }
    if (report) *report = rep;
  }

 private:
  struct Sample {
    double value = 0;   // the depth given (clamped)
    double grid = 0;    // the grid's own depth there
  };

  double clamped(double r) const { return std::isnan(r) ? min_depth_ : std::max(r, min_depth_); }
  // The grid's own value: a missing one (land, on the last grid) counts as MinDepth.
  double unclamped(double r) const { return std::isnan(r) ? min_depth_ : r; }

  // The bilinear value of the clamped nodes (what a grid clamped when read gives,
  // bit for bit) and of the grid's own values.
  bool bilinear(const LonLatGrid& g, bool last, double lon, double lat, Sample& s) const {
    if (!last && !g.covers(lon, lat)) return false;
    const LonLatGrid::Stencil st = g.stencil(lon, lat);
    const double c[4] = {g.at(st.i0, st.j), g.at(st.i1, st.j), g.at(st.i0, st.j + 1), g.at(st.i1, st.j + 1)};
    if (!last && (std::isnan(c[0]) || std::isnan(c[1]) || std::isnan(c[2]) || std::isnan(c[3]))) return false;
    auto blend = [&](auto f) {
      const double a = f(c[0]) * (1 - st.wi) + f(c[1]) * st.wi;
      const double b = f(c[2]) * (1 - st.wi) + f(c[3]) * st.wi;
      return a * (1 - st.wj) + b * st.wj;
    };
    s.value = blend([&](double r) { return clamped(r); });
    s.grid = blend([&](double r) { return unclamped(r); });
    return true;
  }

  // The mean of the values within the angle r of (lon, lat), missing ones skipped on
  // a grid that is not the last; the nearest value when none lies within r.
  bool cell_mean(const LonLatGrid& g, bool last, double lon, double lat, double r, Sample& s) const {
    if (!last && !g.covers(lon, lat)) return false;
    const double r_deg = r / kDegree;
    const int j_lo = std::max(0, static_cast<int>(std::ceil((lat - r_deg - g.lat0) / g.dlat)));
    const int j_hi = std::min(g.nlat - 1, static_cast<int>(std::floor((lat + r_deg - g.lat0) / g.dlat)));
    // Longitudes of a spherical cap of angle r: |dlon| <= asin(sin r / cos lat), every
    // longitude when the cap holds a pole.
    const bool polar = std::fabs(lat) + r_deg >= 90;
    const double half_lon = polar ? 180 : std::asin(std::min(1.0, std::sin(r) / std::cos(lat * kDegree))) / kDegree;
    const double c = g.column_of(lon);
    double i_lo = std::ceil(c - half_lon / g.dlon), i_hi = std::floor(c + half_lon / g.dlon);
    if (g.period > 0) {
      if (i_hi - i_lo + 1 > g.period) i_hi = i_lo + g.period - 1;   // each column once
    } else {
      i_lo = std::max(i_lo, 0.0);
      i_hi = std::min(i_hi, static_cast<double>(g.nlon - 1));
    }
    double sum = 0;
    std::uint64_t n = 0, within = 0;
    for (int j = j_lo; j <= j_hi; ++j)
      for (double ii = i_lo; ii <= i_hi; ++ii) {
        const int i = g.wrap(static_cast<int>(ii));
        if (angle_between(lon, lat, g.lon0 + ii * g.dlon, g.lat(j)) > r) continue;
        ++within;
        const double v = g.at(i, j);
        if (std::isnan(v) && !last) continue;
        sum += unclamped(v);
        ++n;
      }
    if (n == 0) {
      if (within > 0) return false;   // only missing values near the point: the next grid's
      const int j = std::clamp(static_cast<int>(std::lround((lat - g.lat0) / g.dlat)), 0, g.nlat - 1);
      const long ic = std::lround(c);
      const int i = g.period > 0 ? g.wrap(static_cast<int>(ic % g.period))
                                 : static_cast<int>(std::clamp(ic, 0L, static_cast<long>(g.nlon - 1)));
      const double v = g.at(i, j);
      if (std::isnan(v) && !last) return false;
      sum = unclamped(v);
      n = 1;
    }
    s.grid = sum / static_cast<double>(n);
    s.value = std::max(s.grid, min_depth_);
    return true;
  }

  std::vector<LonLatGrid> grids_;
  double radius_, min_depth_;
};

// The grids of FileName by priority, each checked to give depths in the same units and
// reference system as the first that says.
std::vector<LonLatGrid> read_depth_grids(const BuildInputs& in) {
  const std::vector<std::string> files = file_names(in);
  std::vector<LonLatGrid> grids;
  std::string units, units_from, crs, crs_from;
  for (std::size_t k = 0; k < files.size(); ++k) {
    GridAttributes attrs;
    grids.push_back(read_raw_depth_grid(in, files[k], attrs));
    const std::string u = unit_word(attrs.units), c = trimmed(attrs.crs);
    if (!u.empty() && units.empty()) units = u, units_from = files[k];
    else if (!u.empty() && u != units)
      in.bad("FileName", fmt::format("'{}' gives depths in '{}' but '{}' in '{}': the grids of a list must share "
                                     "their units (convert one)", units_from, units, files[k], trimmed(attrs.units)));
    if (!c.empty() && crs.empty()) crs = c, crs_from = files[k];
    else if (!c.empty() && c != crs)
      in.bad("FileName", fmt::format("'{}' and '{}' have different coordinate reference systems ('{}' and '{}'): "
                                     "the grids of a list must share one (reproject one)",
                                     crs_from, files[k], crs.substr(0, 60), c.substr(0, 60)));
  }
  check_no_missing(in, files.back(), grids.back());
  return grids;
}

}  // namespace

std::vector<double> half_edge_angles(std::span<const Vec3> xyz, std::vector<std::array<std::uint32_t, 2>> edges) {
  for (auto& e : edges)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> sum(xyz.size(), 0);
  std::vector<std::uint32_t> count(xyz.size(), 0);
  for (const auto& [a, b] : edges) {
    if (a == b || b >= xyz.size()) continue;
    const double angle = std::atan2(norm(cross(xyz[a], xyz[b])), dot(xyz[a], xyz[b]));
    sum[a] += angle, sum[b] += angle;
    ++count[a], ++count[b];
  }
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = count[i] ? 0.5 * sum[i] / count[i] : 0;
  return sum;
}

std::vector<OptionSpec> depth_grid_options() {
  return {
      str_opt("FileName", "", "netCDF file, or ESRI ASCII grid if the name ends in .asc"),
      str_opt("LonVariable", "", "netCDF longitude variable (empty: detected)"),
      str_opt("LatVariable", "", "netCDF latitude variable (empty: detected)"),
      str_opt("ZVariable", "", "netCDF relief variable (empty: the first 2D variable)"),
      str_opt("Positive", "up", "\"up\": values are elevations (sea floor < 0); \"down\": depths"),
      num_opt("MinDepth", 10, "depths are clamped to at least this (land included), metres"),
      num_opt("MissingAsLand", 0, "1: missing/NaN nodes become MinDepth instead of an error"),
  };
}

namespace {

FieldPtr make_bathymetry(const BuildInputs& in) {
  const Options& o = in.opts;
  const std::string& output = o.string("Output");
  if (output == "depth") return std::make_shared<DepthGridsField>(read_depth_grids(in), o.number("Radius"),
                                                                  o.number("MinDepth"));
  LonLatGrid g = read_depth_grid(in);
  Output out;
  if (output == "wavelength") out = Output::Wavelength;
  else if (output == "hessian") out = Output::Hessian;
  else if (output == "tidal") out = Output::Tidal;
  else if (output == "slope") out = Output::Slope;
  else in.bad("Output", fmt::format("unknown output '{}' (depth, wavelength, hessian, tidal or slope)", output));
  const double min_depth = o.number("MinDepth");
  if (!(min_depth > 0))
    in.bad("MinDepth", "must be positive for the wavelength, hessian, tidal and slope criteria");
  const double depth_ref = o.number("DepthRef");
  if (!(depth_ref > 0)) in.bad("DepthRef", "must be positive");
  double scale = 0;
  if (out == Output::Wavelength) {
    const double lambda = o.number("WaveLengthMin"), n = o.number("PointsPerWaveLength");
    if (!(lambda > 0)) in.bad("WaveLengthMin", "must be positive");
    if (!(n > 0)) in.bad("PointsPerWaveLength", "must be positive");
    scale = lambda / n * std::sqrt(depth_ref);
  }
  if (out == Output::Hessian) {
    const double earth = o.number("EarthRadius");
    if (!(earth > 0)) in.bad("EarthRadius", "must be positive");
    g = hessian_criterion(g, depth_ref, earth);
  }
  if (out == Output::Tidal || out == Output::Slope) {
    const double n = o.number("PointsPerWaveLength");
    if (!(n > 0)) in.bad("PointsPerWaveLength", "must be positive");
    if (out == Output::Tidal) {
      const double period = o.number("Period");
      if (!(period > 0)) in.bad("Period", "must be positive");
      scale = period * std::sqrt(kGravity) / n;
    } else {
      const double earth = o.number("EarthRadius");
      if (!(earth > 0)) in.bad("EarthRadius", "must be positive");
      g = slope_criterion(g, n, earth);
    }
  }
  return std::make_shared<BathymetryField>(std::move(g), o.number("Radius"), out, scale);
}

}  // namespace

KindSpec bathymetry_kind() {
  return {"Bathymetry",
          "Relief grid (netCDF or ESRI ASCII .asc) sampled bilinearly at the longitude/latitude "
          "of the point: the depth H = max(depth, MinDepth), the wavelength criterion "
          "f1 = WaveLengthMin/PointsPerWaveLength*sqrt(DepthRef/H), or the Hessian criterion "
          "f2 = 1/sqrt(|lambda_max|) of the Hessian of H/DepthRef in metres (paper section 3.1); "
          "or the usual physical criteria: the tidal wavelength Period*sqrt(9.81 H)/PointsPerWaveLength "
          "(finer on shelves) and the slope (2 pi/PointsPerWaveLength) H/|grad H| (gradient on the sphere "
          "by the Hessian's centred differences). Feed it to a Threshold to get a size.",
          {
              str_opt("FileName", "",
                      "netCDF file, or ESRI ASCII grid if the name ends in .asc; with Output \"depth\", a "
                      "comma-separated list by priority: the first grid covering a point with a value there "
                      "gives its depth, the next fills the gaps"),
              str_opt("LonVariable", "", "netCDF longitude variable (empty: detected)"),
              str_opt("LatVariable", "", "netCDF latitude variable (empty: detected)"),
              str_opt("ZVariable", "", "netCDF relief variable (empty: the first 2D variable)"),
              str_opt("Positive", "up", "\"up\": values are elevations (sea floor < 0); \"down\": depths"),
              str_opt("Output", "depth",
                      "\"depth\" (H), \"wavelength\" (f1), \"hessian\" (f2), \"tidal\" (T sqrt(gH)/N) or "
                      "\"slope\" ((2 pi/N) H/|grad H|)"),
              num_opt("MinDepth", 10, "depths are clamped to at least this (land included), metres"),
              num_opt("DepthRef", 4000, "reference depth H_ref of f1 and f2, metres"),
              num_opt("WaveLengthMin", 1, "lambda_min of f1: smallest wavelength at H_ref"),
              num_opt("PointsPerWaveLength", 1, "N of f1, of the tidal and of the slope criteria"),
              num_opt("EarthRadius", 6371e3, "radius used for the Hessian's and the slope's metres"),
              num_opt("Radius", 0, "sphere radius for the latitude of a point (0: |X|)"),
              num_opt("MissingAsLand", 0, "1: missing/NaN nodes become MinDepth instead of an error"),
              num_opt("Period", 44712, "T of the tidal criterion, seconds (the M2 tide: 12.42 h)"),
              list_opt("Window", "{W, E, S, N} in degrees: only this box of each netCDF grid (plus one node "
                                 "around) is read, so that a grid larger than memory can be used; empty: whole grids"),
          },
          make_bathymetry};
}

}  // namespace sm::field
