// The size floor of Mesh.MinTimeStep: the background size raised to
// factor * dt * sqrt(g H) (H the depth there), so that no element is asked to be so small
// that a gravity wave crosses it in less than dt (field/time_step_size.cpp's criterion,
// applied as a Max over the whole size field rather than chosen by the script).
#pragma once

#include "field/registry.h"

namespace sm::field {

/// max(size(x), factor * dt * sqrt(9.81 max(depth(x), min_depth))); depth in metres,
/// positive down. Dry points (depth <= 0 with min_depth 0) get no floor.
FieldPtr time_step_floor(FieldPtr size, FieldPtr depth, double dt, double min_depth, double factor);

}  // namespace sm::field
