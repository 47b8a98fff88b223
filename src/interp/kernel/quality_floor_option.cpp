// The one place that decides what the model's being on the sphere or flat changes in the
// 2D mesher: Mesh.QualityFloor's default, and front2d's Gmsh rule.
#include "interp/kernel/quality_floor_option.h"

#include "interp/interpreter.h"
#include "interp/kernel_state.h"

namespace sm::interp {

bool model_on_sphere(const KernelState& k) {
  if (!k.coastlines.empty()) return true;
  for (const auto& [tag, s] : k.model.surfaces())
    if (s.geometry != 0) return true;
  return false;
}

double quality_floor_in_effect(Interpreter& in) {
  const double floor = in.options().number("Mesh.QualityFloor");
  if (in.options().was_set("Mesh.QualityFloor")) return floor;
  return model_on_sphere(in.kernel()) ? floor : 0.0;
}

bool gmsh_rejection_in_effect(const KernelState& k) { return !model_on_sphere(k); }

}  // namespace sm::interp
