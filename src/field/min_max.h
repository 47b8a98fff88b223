// Min / Max of a list of fields, and the argmin diagnostic: which input of a
// Min controls the size at each point (the peers' "which criterion" report).
#pragma once

#include <span>

#include "field/field.h"

namespace sm::field {

/// If `f` is a Min field, writes the minimum to `h` and, per point, the id of
/// the input field that attains it (first in FieldsList order on ties; -1
/// when the list is empty) to `which`, and returns true. Otherwise returns
/// false and leaves both untouched.
bool eval_argmin(const SizeField& f, const EntityRef* on, std::span<const Vec3> pts,
                 std::span<double> h, std::span<int> which);

}  // namespace sm::field
