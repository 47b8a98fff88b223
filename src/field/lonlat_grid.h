// Regular lon/lat grids of node values (bathymetry, gradation background):
// readers for netCDF and ESRI ASCII, and bilinear interpolation with the
// +-180 wrap and clamping at the poles and at regional edges.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "base/vec.h"

namespace sm::field {

/// Node (i, j) is at lon0 + i*dlon, lat0 + j*dlat (degrees, both steps > 0),
/// value v[j*nlon + i]:
///
///   j=nlat-1  +---+---+   north
///             |   |   |
///   j=0       +---+---+   south     i = 0 .. nlon-1, west to east
struct LonLatGrid {
  int nlon = 0, nlat = 0;
  double lon0 = 0, dlon = 1, lat0 = 0, dlat = 1;
  std::vector<double> v;
  /// Columns per 360 degrees when the grid wraps round the globe (column
  /// i + period, if present, repeats column i), else 0.
  int period = 0;

  double at(int i, int j) const { return v[static_cast<std::size_t>(j) * nlon + i]; }
  double& at(int i, int j) { return v[static_cast<std::size_t>(j) * nlon + i]; }
  double lon(int i) const { return lon0 + i * dlon; }
  double lat(int j) const { return lat0 + j * dlat; }

  /// Sets `period` from the spacing (call after filling the geometry).
  void detect_wrap();
  /// Bilinear value at (lon, lat) in degrees: any longitude (wrapped), lat
  /// clamped to the grid rows; outside a regional grid the edge value.
  double interp(double lon_deg, double lat_deg) const;
  /// Wrapped column of a periodic grid (identity otherwise).
  int wrap(int i) const;
};

/// Which netCDF variables hold lon, lat and the values ("" = detect: the
/// first 2D variable, and the coordinate variables of its dimensions).
struct NetcdfGridSpec {
  std::string lon_var, lat_var, z_var;
};

/// Reads a 2D grid from a netCDF file (any of classic CDF-1/2/5 or netCDF-4),
/// applying scale_factor/add_offset and turning _FillValue/missing_value into
/// NaN. Longitudes/latitudes must be evenly spaced (either direction).
/// Throws FieldError FileError (file, variable) on any problem.
LonLatGrid read_netcdf_grid(const std::filesystem::path& file, const NetcdfGridSpec& spec);

/// Reads an ESRI ASCII grid (.asc; header ncols, nrows, xll{corner,center},
/// yll{corner,center}, cellsize, [nodata_value]; first data row = north).
/// NODATA nodes become NaN. The header is checked before anything is
/// allocated: finite values, whole sizes >= 2, cellsize > 0, nodes on the globe,
/// and at least two bytes of data per announced value. Throws FieldError
/// FileError naming the file, the line and the value.
LonLatGrid read_esri_ascii_grid(const std::filesystem::path& file);
/// Same, from the text of a grid already in memory (`file` names it in errors).
LonLatGrid parse_esri_ascii_grid(std::string_view text, const std::filesystem::path& file);

/// Longitude and latitude (degrees) of a 3D point; `radius` <= 0 uses |p|.
void lonlat_of(const Vec3& p, double radius, double& lon_deg, double& lat_deg);
/// The 3D point of (lon, lat) in degrees on a sphere of the given radius.
Vec3 point_of(double lon_deg, double lat_deg, double radius);

}  // namespace sm::field
