// Fuzz entry: the GSHHS binary reader on the bytes as they are.
#include <span>

#include "coast/read_gshhs.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"

namespace sm::fuzz {

void run_gshhs_input(const std::uint8_t* data, std::size_t size) {
  check_coastline("gshhs", coast::read_gshhs_bytes(std::span<const unsigned char>(data, size), "fuzz.b"));
}

}  // namespace sm::fuzz
