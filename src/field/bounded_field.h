// A field that can answer "the value, or only that it is above some limit" more
// cheaply than the value itself: Threshold asks its input this way beyond DistMax,
// and a Distance field stops its nearest-shore search there (field/distance.cpp).
#pragma once

#include <span>

#include "base/vec.h"

namespace sm::field {

class BoundedEval {
 public:
  virtual ~BoundedEval() = default;
  /// As SizeField::eval, exact where the value is at most `limit`; elsewhere any value
  /// above `limit`. For fields whose value does not depend on the entity.
  virtual void eval_below(std::span<const Vec3> pts, double limit, std::span<double> h) const = 0;
};

}  // namespace sm::field
