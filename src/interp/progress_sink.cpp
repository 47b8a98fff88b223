// The kernel's progress sink under the verbosity option (see progress_sink.h).
#include "interp/progress_sink.h"

#include "interp/interpreter.h"

namespace sm::interp {

Progress* progress_sink(Interpreter& in) {
  if (!in.kernel().progress) return nullptr;
  return in.options().number("General.Verbosity") >= 4 ? in.kernel().progress : nullptr;
}

}  // namespace sm::interp
