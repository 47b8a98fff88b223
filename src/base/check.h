// SM_ASSERT: a broken internal invariant is a bug, not a diagnostic. It
// reports the library file:line and aborts, in every build type, so that a
// bug never turns into a silently wrong mesh. The CLI maps the abort path to
// exit code 3 (internal error).
#pragma once

namespace sm {

[[noreturn]] void assertion_failed(const char* cond, const char* msg, const char* file, int line);

}  // namespace sm

#define SM_ASSERT(cond, msg)                                          \
  do {                                                                \
    if (!(cond)) ::sm::assertion_failed(#cond, msg, __FILE__, __LINE__); \
  } while (0)
