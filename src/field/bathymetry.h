// The paper's bathymetry criteria (section 3.1) on a lon/lat grid: depth H,
// the gravity-wave wavelength criterion f1 and the Hessian criterion f2.
#pragma once

#include "field/lonlat_grid.h"

namespace sm::field {

/// Node-wise f2 = 1/sqrt(|lambda_max|) of the Hessian of depth/depth_ref on
/// the sphere of radius `radius` (metres), by centred finite differences in
/// (lon, lat) with the metric terms of the sphere; 1e22 where the Hessian
/// vanishes. `depth` holds positive depths.
LonLatGrid hessian_criterion(const LonLatGrid& depth, double depth_ref, double radius);

}  // namespace sm::field
