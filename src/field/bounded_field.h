// Fields that can answer more cheaply than with their value: "the value, or only that
// it is above some limit" (a Distance stops its nearest-shore search there, so a
// Threshold asks its input this way beyond DistMax), and "the value, where it is below
// the size so far" (a Threshold inside a Min; field/min_max.cpp).
#pragma once

#include <span>

#include "base/vec.h"
#include "field/field.h"

namespace sm::field {

class BoundedEval {
 public:
  virtual ~BoundedEval() = default;
  /// As SizeField::eval, exact where the value is at most the limit; elsewhere any
  /// value above it. `limit`: one value for all points, or one per point. For fields
  /// whose value does not depend on the entity.
  virtual void eval_below(std::span<const Vec3> pts, std::span<const double> limit, std::span<double> h) const = 0;
};

class MinInput {
 public:
  virtual ~MinInput() = default;
  /// h[i] = the value at pts[i] wherever that is below h[i] (what a Min does with its
  /// next input), without computing the value where it certainly is not.
  virtual void lower(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const = 0;
  /// Whether lower() costs less where h is already smaller (a search cut short): a Min
  /// then asks such inputs last, once the others have lowered h.
  virtual bool prunes() const { return true; }
};

}  // namespace sm::field
