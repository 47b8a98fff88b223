// libFuzzer target: the quality floor on random coasts (entry in fuzz_floor_entry.cpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_floor_entry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sm::fuzz::run_floor_input(data, size);
  return 0;
}
