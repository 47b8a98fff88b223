// The Mesh.MeshSize* options of a run (CharacteristicLength* are their
// aliases) as the field kernel's SizePolicyOptions: the one place the mesher
// reads them from (gmsh-reference 4.4).
#pragma once

#include "field/size_policy.h"
#include "interp/options.h"

namespace sm::interp {

field::SizePolicyOptions size_policy_from_options(const Options& options);

}  // namespace sm::interp
