// UTF-8 validation of one sequence: what the diagnostics printer (lang/diagnostics.cpp)
// and the JSON writer (base/json_text.cpp) both need to pass text through or replace it.
#pragma once

#include <cstddef>
#include <string_view>

namespace sm::base {

/// Length of the valid UTF-8 sequence starting at s[i] (1 for an ASCII byte), 0 when the
/// bytes there are not one (a stray continuation byte, an overlong or cut sequence).
inline std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c >= 0xE0 && c <= 0xEF) n = 3;
  else if (c >= 0xF0 && c <= 0xF4) n = 4;
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}

}  // namespace sm::base
