// Direct construction of a Distance field from sample points computed by the
// caller (coastline importers, tests, benchmarks).
#pragma once

#include <vector>

#include "field/registry.h"

namespace sm::field {

/// Distance to the nearest of `samples` (chord distance). Throws BadValue on
/// a non-finite sample.
FieldPtr make_distance_field(std::vector<Vec3> samples);

}  // namespace sm::field
