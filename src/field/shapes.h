// Helpers shared by the region fields (Box, Ball, Cylinder).
#pragma once

namespace sm::field {

/// VIn inside, then a linear ramp to VOut over `thickness` beyond the region
/// (docs/fields.md: VIn + (d/Thickness)(VOut - VIn)), then VOut.
inline double ramp_out(double d_outside, double thickness, double v_in, double v_out) {
  if (thickness > 0 && d_outside <= thickness) return v_in + d_outside / thickness * (v_out - v_in);
  return v_out;
}

}  // namespace sm::field
