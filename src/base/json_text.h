// JSON values as text, for the files written as JSON (--stats, --diagnostics): strings
// quoted and escaped, numbers in their shortest round-trip form.
#pragma once

#include <string>
#include <string_view>

namespace sm::base {

/// `s` as a JSON string: quoted, '"', '\\' and control characters escaped; a byte that is
/// not part of valid UTF-8 becomes U+FFFD, so that the file is always valid UTF-8.
std::string json_string(std::string_view s);

/// A finite number as the shortest text that reads back to it; "null" for NaN and the
/// infinities, which JSON cannot hold.
std::string json_number(double v);

}  // namespace sm::base
