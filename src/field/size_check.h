// The mesher's guard on the sizes a field gives: every value must be a finite,
// positive length, or meshing stops with a typed error naming the field and the point.
#pragma once

#include <string>

#include "field/registry.h"

namespace sm::field {

/// `f` (field `id`, of kind `kind`) with each size it returns checked: the first value
/// of a batch that is not finite and positive throws FieldError BadValue with
/// field_id = id and point = where it was evaluated. Batches are checked in the order
/// the caller evaluates them, so the mesher's deterministic order (and its
/// deterministic choice of the first failed chunk) makes the reported point the same
/// for every thread count.
FieldPtr checked_size_field(FieldPtr f, int id, std::string kind);

}  // namespace sm::field
