// An accuracy field gamma(x) = g everywhere: the coarsening tests' simplest input.
#pragma once

#include <span>

#include "base/vec.h"
#include "coast/coarsen.h"

namespace sm::testing {

inline sm::coast::AccuracyFn constant_accuracy(double g) {
  return [g](std::span<const Vec3>, std::span<double> out) {
    for (double& x : out) x = g;
  };
}

}  // namespace sm::testing
