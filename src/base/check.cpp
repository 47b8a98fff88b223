// The one place that turns a broken invariant into a report and an exit.
#include "base/check.h"

#include <cstdio>
#include <cstdlib>

namespace sm {

void assertion_failed(const char* cond, const char* msg, const char* file, int line) {
  std::fprintf(stderr, "stereomesh: internal error: %s (%s) at %s:%d\n", msg, cond, file, line);
  std::fprintf(stderr, "stereomesh: this is a bug; please report it with the script that triggered it\n");
  std::fflush(stderr);
  std::_Exit(3);
}

}  // namespace sm
