// Fuzz entry: the GMT lon/lat text reader on the bytes as text.
#include <string_view>

#include "coast/read_lonlat_text.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"

namespace sm::fuzz {

void run_lonlat_text_input(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check_coastline("lonlat_text", coast::read_lonlat_text_string(text, "fuzz.txt"));
}

}  // namespace sm::fuzz
