// Small line/number scanning helpers shared by the text readers (no locale, no exceptions).
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
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
  // Fast path for the plain decimals of the shoreline files ("-12.345678"): at most 15
  // digits make an integer m < 2^53 and at most 22 decimals a power 10^k, both exact
  // doubles, so m / 10^k is one correctly rounded operation: the value from_chars gives
  // (Clinger 1990). Anything else (exponents, more digits, no digit before the point)
  // goes to from_chars.
  {
    static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char* p = s.data();
    const char* const end = p + s.size();
    const bool negative = p != end && *p == '-';
    if (negative) ++p;
    const char* const first = p;
    std::uint64_t m = 0;
    int digits = 0, decimals = 0;
    while (p != end && *p >= '0' && *p <= '9') {
      m = m * 10 + static_cast<unsigned>(*p++ - '0');
      ++digits;
    }
    if (p != first && p != end && *p == '.') {
      ++p;
      while (p != end && *p >= '0' && *p <= '9') {
        m = m * 10 + static_cast<unsigned>(*p++ - '0');
        ++digits;
        ++decimals;
      }
    }
    if (p != first && digits <= 15 && (p == end || (*p != 'e' && *p != 'E'))) {
      const double x = static_cast<double>(m) / kPow10[decimals];
      v = negative ? -x : x;
      s.remove_prefix(static_cast<std::size_t>(p - s.data()));
      return true;
    }
  }
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
