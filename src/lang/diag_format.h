// The diagnostic kinds' formats as compile-time constants, and DiagFormat<Args...>: a kind
// checked against the arguments it is reported with when the call is compiled, so that a
// wrong argument count or an argument of the wrong type for its slot does not build.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

namespace sm::lang {

enum class Diag : std::uint16_t {
#define DIAG(name, severity, kebab, format) name,
#include "lang/diag_kinds.def"
#undef DIAG
  kCount
};

/// Each kind's fmt format, indexed by Diag (diag_kinds.def).
inline constexpr std::string_view kDiagFormats[] = {
#define DIAG(name, severity, kebab, format) format,
#include "lang/diag_kinds.def"
#undef DIAG
};

/// How many arguments `format` reads: its automatic slots ("{}", "{:g}") or, when it numbers
/// them ("{0}", "{1:.3f}"), one more than the highest number; "{{" and "}}" are literal
/// braces. -1 for a brace that opens no slot or a slot that is not closed.
constexpr int diag_format_arity(std::string_view format) {
  int automatic = 0, numbered = 0;
  for (std::size_t i = 0; i < format.size(); ++i) {
    const char c = format[i];
    if (c == '}') {
      if (i + 1 >= format.size() || format[i + 1] != '}') return -1;
      ++i;
      continue;
    }
    if (c != '{') continue;
    if (i + 1 < format.size() && format[i + 1] == '{') {
      ++i;
      continue;
    }
    const std::size_t close = format.find('}', i);
    if (close == std::string_view::npos) return -1;
    int index = -1;
    for (std::size_t k = i + 1; k < close && format[k] >= '0' && format[k] <= '9'; ++k)
      index = (index < 0 ? 0 : index * 10) + (format[k] - '0');
    if (index < 0) {
      ++automatic;
    } else if (index + 1 > numbered) {
      numbered = index + 1;
    }
    i = close;
  }
  return automatic > numbered ? automatic : numbered;
}

namespace detail {
// Not constexpr: reached while checking a DiagFormat, it makes the call a compile error
// whose note names this function.
inline void diag_argument_count_differs_from_format() {}
}  // namespace detail

/// A diagnostic kind to be reported with arguments of types Args. Built from a Diag constant
/// at compile time (consteval): fmt checks every slot of the kind's format against its
/// argument's type, and the number of arguments must be the number the format reads. A kind
/// chosen at run time does not convert: pick it with a switch whose every case reports.
template <class... Args>
class DiagFormat {
 public:
  consteval DiagFormat(Diag kind)  // NOLINT: implicit, so that callers write Diag::Name
      : kind_(kind) {
    const std::string_view format = kDiagFormats[static_cast<std::size_t>(kind)];
#if !defined(__clang__) || __clang_major__ >= 16
    // clang before 16 refuses fmt's consteval check inside this consteval constructor (it
    // takes the nested call for an immediate invocation); the project's own build (g++,
    // CMakeLists.txt) checks every slot's type, the fuzz build (clang) the count only.
    const fmt::format_string<Args...> checked(format);
    static_cast<void>(checked);
#endif
    if (diag_format_arity(format) != static_cast<int>(sizeof...(Args)))
      detail::diag_argument_count_differs_from_format();
  }
  constexpr Diag kind() const { return kind_; }
  std::string_view format() const { return kDiagFormats[static_cast<std::size_t>(kind_)]; }

 private:
  Diag kind_;
};

/// The kind's message for `args` (the types were checked when the DiagFormat was built).
template <class... Args>
std::string format_diag(std::type_identity_t<DiagFormat<Args...>> kind, const Args&... args) {
  return fmt::vformat(kind.format(), fmt::make_format_args(args...));
}

}  // namespace sm::lang
