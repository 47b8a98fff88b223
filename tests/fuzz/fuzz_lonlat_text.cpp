// libFuzzer target: the lonlat_text reader on arbitrary bytes (entry in fuzz_lonlat_text_entry.cpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_reader_entries.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sm::fuzz::run_lonlat_text_input(data, size);
  return 0;
}
