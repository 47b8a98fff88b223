// Hook: evaluation of a syntactically valid fuzz input. With the interpreter
// linked (SM_FUZZ_WITH_INTERP) it runs the script with Printf output discarded
// (tests/fuzz/run.sh runs the fuzzer inside a scratch directory, so files the
// script writes land there); without it, it does nothing.
#pragma once

#include <string>

namespace sm::fuzz {

void evaluate_parsed(const std::string& text);

}  // namespace sm::fuzz
