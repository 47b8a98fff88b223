// Wall time of a stage, for the kernel's own timing fields (MeshStats, 1D and 2D results).
#pragma once

#include <chrono>

namespace sm {

/// Seconds of wall time since t0, on the steady clock.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace sm
