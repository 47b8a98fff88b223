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
  /// The four nodes and weights of the bilinear value at (lon, lat): the value is
  /// (at(i0,j)(1-wi) + at(i1,j)wi)(1-wj) + (at(i0,j+1)(1-wi) + at(i1,j+1)wi)wj.
  struct Stencil {
    int i0 = 0, i1 = 0, j = 0;
    double wi = 0, wj = 0;
  };
  Stencil stencil(double lon_deg, double lat_deg) const;
  /// Bilinear value at (lon, lat) in degrees: any longitude (wrapped), lat
  /// clamped to the grid rows; outside a regional grid the edge value.
  double interp(double lon_deg, double lat_deg) const;
  /// Whether (lon, lat) lies within the grid's nodes (any longitude on a
  /// periodic grid), where interp does not clamp to an edge.
  bool covers(double lon_deg, double lat_deg) const;
  /// The column of a regional grid nearest in longitude to lon_deg (mod 360),
  /// as a real index (may lie outside 0 .. nlon-1); on a periodic grid not wrapped.
  double column_of(double lon_deg) const;
  /// Wrapped column of a periodic grid (identity otherwise).
  int wrap(int i) const;
};

/// Which netCDF variables hold lon, lat and the values ("" = detect: the
/// first 2D variable, and the coordinate variables of its dimensions).
struct NetcdfGridSpec {
  std::string lon_var, lat_var, z_var;
  /// {W, E, S, N} in degrees, W < E, S < N: only the nodes within, plus one on each
  /// side, are read (nc_get_vara); all the columns when the box crosses the grid's seam.
  /// Empty: the whole grid.
  std::vector<double> window;
};

/// What a netCDF relief variable says of itself, for checking that several grids
/// agree: its `units` attribute and its coordinate reference system (the text of
/// its grid_mapping variable: crs_wkt, spatial_ref, epsg_code or
/// grid_mapping_name); empty when the file does not say.
struct GridAttributes {
  std::string units, crs;
};

/// Reads a 2D grid from a netCDF file (any of classic CDF-1/2/5 or netCDF-4),
/// applying scale_factor/add_offset and turning _FillValue/missing_value into
/// NaN. Longitudes/latitudes must be evenly spaced (either direction).
/// Throws FieldError FileError (file, variable) on any problem.
LonLatGrid read_netcdf_grid(const std::filesystem::path& file, const NetcdfGridSpec& spec,
                            GridAttributes* attrs = nullptr);

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
