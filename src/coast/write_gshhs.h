// Writer of the GSHHS 2.x native binary (the layout read_gshhs.h reads): a large
// shoreline exported as text can be stored and read back as the compact binary
// (8 bytes a point instead of about 23), for instance the whole full-resolution GSHHG.
#pragma once

#include <string>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

/// The GSHHS 2.x bytes of `c` (44-byte headers, big-endian micro-degrees). Every ring must
/// be closed with at most 2^31 - 1 points and coordinates within what read_gshhs accepts;
/// an open ring or a point off the globe is an error naming its record. Points are rounded
/// to the nearest micro-degree (the text exports carry 6 decimals, so nothing is lost).
/// The area in the header is the ring's spherical area (ring_area_km2) in 1/10 km^2.
Result<std::vector<unsigned char>> gshhs_bytes(const Coastline& c);

/// Writes gshhs_bytes(c) to `path` through a temporary file renamed into place.
Result<bool> write_gshhs(const Coastline& c, const std::string& path);

}  // namespace sm::coast
