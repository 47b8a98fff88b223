// The paper's bathymetry criteria (section 3.1) on a lon/lat grid: depth H,
// the gravity-wave wavelength criterion f1, the Hessian criterion f2, and the
// tidal-wavelength and slope criteria.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "field/depth_clamp.h"
#include "field/lonlat_grid.h"
#include "field/registry.h"

namespace sm::field {

/// Node-wise f2 = 1/sqrt(|lambda_max|) of the Hessian of depth/depth_ref on
/// the sphere of radius `radius` (metres), by centred finite differences in
/// (lon, lat) with the metric terms of the sphere; 1e22 where the Hessian
/// vanishes. `depth` holds positive depths.
LonLatGrid hessian_criterion(const LonLatGrid& depth, double depth_ref, double radius);

/// Node-wise slope criterion (2 pi / n) H / |grad H| on the sphere of radius `radius`
/// (metres), |grad H| by the same centred differences as hessian_criterion; 1e22
/// where the bottom is flat. `depth` holds positive depths.
LonLatGrid slope_criterion(const LonLatGrid& depth, double n, double radius);

/// A Bathymetry field with Output "depth": positive depths from one relief grid or a
/// list of them by priority (the first grid that covers a point and has values there
/// wins), clamped to MinDepth. Besides eval's bilinear values it gives the depths at
/// mesh nodes by cell averaging, and the clamp's account.
class GridDepthField : public SizeField {
 public:
  /// Depths at `pts`. With `half_size` empty, eval's bilinear values; else at point i
  /// the mean of the grid values (cell centres) lying within the angle half_size[i]
  /// (radians on the sphere), or the nearest one's when none does, then clamped.
  /// `report`, if given, receives the clamp's account.
  virtual void node_depths(std::span<const Vec3> pts, std::span<const double> half_size, std::span<double> out,
                           DepthClampReport* report) const = 0;
};

/// Half the mean angle (radians, about the origin) of the edges incident to each
/// node: the angle Mesh.DepthSampling 1 averages the grid cells within. `edges` are
/// node index pairs in any order and orientation, repeats counted once; a node on no
/// edge gets 0 (its nearest cell).
std::vector<double> half_edge_angles(std::span<const Vec3> xyz, std::vector<std::array<std::uint32_t, 2>> edges);

/// The relief grid of a kind with depth_grid_options(), as positive depths clamped
/// to MinDepth (BadValue / FileError naming the field).
LonLatGrid read_depth_grid(const BuildInputs& in);
/// FileName, LonVariable, LatVariable, ZVariable, Positive, MinDepth, MissingAsLand.
std::vector<OptionSpec> depth_grid_options();

}  // namespace sm::field
