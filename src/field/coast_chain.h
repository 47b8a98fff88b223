// A coast piece as size fields see it: the curves of one ring chained end to
// end and sampled in order (ChannelWidth reads these from the model).
#pragma once

#include <vector>

#include "base/vec.h"

namespace sm::field {

struct CoastChain {
  std::vector<Vec3> points;
  bool closed = false;  ///< the last sample connects back to the first
  /// Where the water is, seen from outside the sphere (or above a flat model's
  /// plane) walking along the samples: +1 on the left, -1 on the right, 0 not
  /// known (both sides are measured; on the coast the narrower counts).
  int water_side = 0;
};

}  // namespace sm::field
