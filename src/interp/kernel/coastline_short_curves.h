// The coast curves that grade the size beside them (field/short_curve_grading.h): the dams
// across closed passages are two-point curves far shorter than the coast edges around them.
#pragma once

#include <vector>

#include "field/registry.h"
#include "interp/kernel_state.h"

namespace sm::interp {

/// How fast the size grows away from a dam's ends (per metre of distance): the edges beside
/// it grow from its length by a ratio of about 1.5.
inline constexpr double kShortCurveGrowth = 0.5;

/// The two-point coast curves of every imported Coastline (no open boundary), tags sorted.
std::vector<int> coastline_two_point_curves(const KernelState& k);

/// `background` (null: null) graded from each two-point coast curve shorter than the size at
/// its middle: both its end points seed min(size, length + kShortCurveGrowth * distance).
/// No such curve: `background` as it is.
field::FieldPtr with_short_curve_grading(const KernelState& k, field::FieldPtr background);

}  // namespace sm::interp
