// Small line/number scanning helpers shared by the text readers (no locale, no exceptions).
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string_view>

namespace sm::coast::detail {

/// Splits the next line off `text` (without its '\n' or '\r\n').
inline bool next_line(std::string_view& text, std::string_view& line) {
  if (text.empty()) return false;
  const std::size_t e = text.find('\n');
  line = text.substr(0, e);
  text = e == std::string_view::npos ? std::string_view{} : text.substr(e + 1);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return true;
}

inline void skip_space(std::string_view& s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == ',')) s.remove_prefix(1);
}

/// Parses one finite double; false on garbage, NaN or infinity.
inline bool take_double(std::string_view& s, double& v) {
  skip_space(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc{} || !std::isfinite(v)) return false;
  s.remove_prefix(static_cast<std::size_t>(r.ptr - s.data()));
  return true;
}

inline bool take_long(std::string_view& s, long long& v) {
  skip_space(s);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc{}) return false;
  s.remove_prefix(static_cast<std::size_t>(r.ptr - s.data()));
  return true;
}

inline bool only_space_left(std::string_view s) {
  skip_space(s);
  return s.empty();
}

}  // namespace sm::coast::detail
