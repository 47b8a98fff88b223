// Whether a point lies on land: the shoreline ring that holds it. A region (box or polygon)
// that no coastline crosses is all ocean unless a land ring holds it (region.cpp,
// region_polygon.cpp).
#pragma once

#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

/// The first closed land ring (level 1, not round a pole) that holds p, tried with the
/// ring's longitudes as they are and shifted by -360 and +360 degrees (a ring past the
/// dateline runs past +-180); null when p lies in none.
const Ring* land_ring_holding(const std::vector<Ring>& rings, geo::LonLat p);

}  // namespace sm::coast
