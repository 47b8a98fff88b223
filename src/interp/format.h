// Printf/Sprintf formatting with Gmsh 4.8.4's rules: the format is cut at each
// '%', each piece is formatted with one argument, and a format without any
// directive dumps its arguments as " [0]v0 [1]v1 ...".
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "lang/diag_format.h"

namespace sm::interp {

/// One Printf argument: a number, or a string (a native extension: Gmsh 4.8.4
/// accepts only numbers).
using FormatArg = std::variant<double, std::string>;

struct FormatResult {
  bool ok = true;
  std::string text;     ///< the formatted text when ok
  lang::Diag kind = lang::Diag::kCount;   ///< the Format* kind of diag_kinds.def when not ok
  std::string error;    ///< why it failed otherwise: that kind's message
  int arg_index = -1;   ///< argument the error is about, -1 for the format itself
};

/// Formats like Gmsh's Printf: "%g %e %f %G %E %F %a" take numbers, "%d %i %o
/// %u %x %X %c" take numbers truncated toward zero (Gmsh 4.8.4 prints garbage
/// there), "%s" takes a string and "%%" is a literal '%' that takes no
/// argument. Too few or too many arguments is an error, as in Gmsh.
FormatResult format_gmsh(std::string_view fmt, const std::vector<FormatArg>& args);

/// Gmsh's "%g" of one number, as used for list dumps and Str/StrCat of numbers.
std::string format_g(double v);

}  // namespace sm::interp
