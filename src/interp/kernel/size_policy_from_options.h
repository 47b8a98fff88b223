// The Mesh.MeshSize* options of a run (CharacteristicLength* are their
// aliases) as the field kernel's SizePolicyOptions: the one place the mesher
// reads them from (docs/fields.md); and Mesh.ElementsAcrossChannels, the
// coast's channel widths inside the Min of the size.
#pragma once

#include <string>

#include "field/registry.h"
#include "field/size_policy.h"
#include "interp/options.h"

namespace sm::interp {

class Interpreter;

field::SizePolicyOptions size_policy_from_options(const Options& options);

/// Why Mesh.ElementsAcrossChannels cannot be used (nothing when it can): 0 < N < 1.
OptionRefusal check_elements_across_channels(const Options& options);

/// `background` (may be null) with, when Mesh.ElementsAcrossChannels = N > 0 and a
/// coastline is imported, the ChannelWidth of every imported coastline's curves
/// (ElementsAcross N, SizeMin/SizeMax the Mesh.MeshSizeMin/Max) inside its Min, on the
/// surfaces bounded by those curves and on their boundary curves. Otherwise
/// `background` as it is.
field::FieldPtr with_channel_sizes(Interpreter& in, field::FieldPtr background);

}  // namespace sm::interp
