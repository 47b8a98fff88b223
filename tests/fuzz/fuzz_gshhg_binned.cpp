// libFuzzer target: the binned GSHHG reader on arbitrary bytes (entry in fuzz_gshhg_binned_entry.cpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_reader_entries.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sm::fuzz::run_gshhg_binned_input(data, size);
  return 0;
}
