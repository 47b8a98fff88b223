// The size graded away from short boundary curves (the dams across closed passages:
// src/interp/kernel/coastline.cpp): a curve of length L far below the size around it gets
// one edge of length L between edges of the full size, and the triangles on it are needles
// whose corners never move. Capping the size at L + growth * distance from its ends lets
// the 1D and 2D meshes grow from L by a ratio of about 1 + growth instead.
#pragma once

#include <vector>

#include "base/vec.h"
#include "field/registry.h"

namespace sm::field {

/// A point the size grows from: min(size, length + growth * |x - at|) (chord distance).
struct GradingSeed {
  Vec3 at;
  double length = 0;
};

/// min(size(x), min over the seeds of seed.length + growth * |x - seed.at|); growth > 0.
FieldPtr short_curve_grading(FieldPtr size, std::vector<GradingSeed> seeds, double growth);

}  // namespace sm::field
