// Fuzz entry: the ESRI ASCII grid reader on the bytes as text.
#include <string_view>

#include "field/error.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"

namespace sm::fuzz {

void run_esri_input(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    check_grid("esri", field::parse_esri_ascii_grid(text, "fuzz.asc"));
  } catch (const field::FieldError& e) {
    if (e.code() != field::FieldErrc::FileError) reader_violated("esri", "an error that is not a FileError");
  }
}

}  // namespace sm::fuzz
