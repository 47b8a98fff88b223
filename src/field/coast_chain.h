// A coast piece as size fields see it: the curves of one ring chained end to
// end and sampled in order (ChannelWidth reads these from the model).
#pragma once

#include <vector>

#include "base/vec.h"

namespace sm::field {

struct CoastChain {
  std::vector<Vec3> points;
  bool closed = false;  ///< the last sample connects back to the first
};

}  // namespace sm::field
