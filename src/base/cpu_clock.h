// The process's CPU clock (every thread): what a stage costs on a loaded machine, where its
// wall time leans on the load.
#pragma once

#include <time.h>

namespace sm {

/// CPU seconds the process has used so far (all threads), 0 when the clock is unavailable.
inline double process_cpu_seconds() {
  timespec t{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0) return 0;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace sm
