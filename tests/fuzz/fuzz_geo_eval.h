// Hook: evaluation of a syntactically valid fuzz input. With the interpreter
// linked (SM_FUZZ_WITH_INTERP) it runs the script in a scratch directory with
// output discarded; without it, it does nothing.
#pragma once

#include <string>

namespace sm::fuzz {

void evaluate_parsed(const std::string& text);

}  // namespace sm::fuzz
