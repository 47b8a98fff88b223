// libFuzzer target: lexer + parser (+ evaluator when linked) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fuzz_geo_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sm::fuzz::run_geo_input(data, size);
  return 0;
}
