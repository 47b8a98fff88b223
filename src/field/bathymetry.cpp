// Bathymetry field: reads a netCDF or ESRI ASCII relief grid and gives, at
// the lon/lat of each 3D point, the depth H (clamped to MinDepth), the
// wavelength criterion f1 = lambda_min/N sqrt(H_ref/H) or the Hessian
// criterion f2 = 1/sqrt(|lambda_max|) of the paper's section 3.1.
#include "field/bathymetry.h"

#include <algorithm>
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

enum class Output { Depth, Wavelength, Hessian, Tidal, Slope };

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

LonLatGrid read_depth_grid(const BuildInputs& in) {
  const Options& o = in.opts;
  const std::string& file = o.string("FileName");
  if (file.empty()) in.bad("FileName", "no bathymetry file given");
  const auto path = in.path(file);
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  LonLatGrid g;
  try {
    g = ext == ".asc" ? read_esri_ascii_grid(path)
                      : read_netcdf_grid(path, {o.string("LonVariable"), o.string("LatVariable"),
                                                o.string("ZVariable")});
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
  const bool missing_as_land = o.number("MissingAsLand") != 0;
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i) {
      double& v = g.at(i, j);
      if (std::isnan(v)) {
        if (!missing_as_land) {
          FieldError e(FieldErrc::FileError,
                       fmt::format("{}: missing or NaN value at lon {}, lat {} (set MissingAsLand "
                                   "= 1 to treat missing nodes as land)", path.string(), g.lon(i),
                                   g.lat(j)));
          e.file = path.string();
          e.field_id = in.id;
          throw e;
        }
        v = min_depth;
        continue;
      }
      // The deepest trench is 11 km and the highest summit 9 km: a relief beyond
      // 1000 km is a unit or packing error (a scale_factor of 1e300, say).
      if (std::fabs(v) > kMaxRelief) {
        FieldError e(FieldErrc::FileError,
                     fmt::format("{}: relief {} m at lon {}, lat {} is not an Earth depth or height in metres "
                                 "(check the file's scale_factor, add_offset and units)",
                                 path.string(), v, g.lon(i), g.lat(j)));
        e.file = path.string();
        e.field_id = in.id;
        throw e;
      }
      v = std::max(sign * v, min_depth);
    }
  return g;
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
  LonLatGrid g = read_depth_grid(in);
  const std::string& output = o.string("Output");
  Output out;
  if (output == "depth") out = Output::Depth;
  else if (output == "wavelength") out = Output::Wavelength;
  else if (output == "hessian") out = Output::Hessian;
  else if (output == "tidal") out = Output::Tidal;
  else if (output == "slope") out = Output::Slope;
  else in.bad("Output", fmt::format("unknown output '{}' (depth, wavelength, hessian, tidal or slope)", output));
  const double min_depth = o.number("MinDepth");
  if (out != Output::Depth && !(min_depth > 0))
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
              str_opt("FileName", "", "netCDF file, or ESRI ASCII grid if the name ends in .asc"),
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
          },
          make_bathymetry};
}

}  // namespace sm::field
