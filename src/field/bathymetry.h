// The paper's bathymetry criteria (section 3.1) on a lon/lat grid: depth H,
// the gravity-wave wavelength criterion f1, the Hessian criterion f2, and the
// tidal-wavelength and slope criteria.
#pragma once

#include <vector>

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

/// The relief grid of a kind with depth_grid_options(), as positive depths clamped
/// to MinDepth (BadValue / FileError naming the field).
LonLatGrid read_depth_grid(const BuildInputs& in);
/// FileName, LonVariable, LatVariable, ZVariable, Positive, MinDepth, MissingAsLand.
std::vector<OptionSpec> depth_grid_options();

}  // namespace sm::field
