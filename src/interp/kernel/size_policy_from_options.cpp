// Mesh.MeshSize{Factor,Min,Max,FromPoints,ExtendFromBoundary,FromCurvature} ->
// field::SizePolicyOptions. Each CharacteristicLength* alias shares its option's
// slot in the registry, so reading the current names sees either spelling.
#include "interp/kernel/size_policy_from_options.h"

#include <array>
#include <string_view>

#include "base/check.h"

namespace sm::interp {

field::SizePolicyOptions size_policy_from_options(const Options& options) {
  static constexpr std::array<std::string_view, 6> kNames = {
      "Mesh.MeshSizeFactor",   "Mesh.MeshSizeMin",
      "Mesh.MeshSizeMax",      "Mesh.MeshSizeFromPoints",
      "Mesh.MeshSizeExtendFromBoundary", "Mesh.MeshSizeFromCurvature"};
  field::SizePolicyOptions out;
  for (std::string_view name : kNames) {
    const bool known = field::set_size_option(out, name, options.number(name));
    SM_ASSERT(known, "size option missing from field::set_size_option");
  }
  return out;
}

}  // namespace sm::interp
