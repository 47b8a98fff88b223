// TextAttributes("Font", "Courier", "FontSize", "12", "Align", "Center"): the
// style of a view's T2/T3 text packed into one number, as Gmsh 4.8.4 returns
// it: (align << 16) | (font << 8) | size, with font and align the indices
// below (tests/scripts/strings/text_attributes.geo holds `gmsh -0`'s output).
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "interp/builtins/builtins.h"

namespace sm::interp {
namespace {

// Gmsh's font list, in its order ("Available fonts" in `gmsh -0`'s log).
constexpr std::string_view kFonts[] = {
    "Times-Roman", "Times-Bold",      "Times-Italic",    "Times-BoldItalic", "Helvetica",
    "Helvetica-Bold", "Helvetica-Oblique", "Helvetica-BoldOblique", "Courier", "Courier-Bold",
    "Courier-Oblique", "Courier-BoldOblique", "Symbol", "ZapfDingbats", "Screen",
};

// Alignment names and their codes; Gmsh also takes these three short forms
// in lower case, and nothing else in another case.
struct Align {
  std::string_view name;
  int code;
};
constexpr Align kAligns[] = {
    {"BottomLeft", 0}, {"Left", 0},        {"left", 0},      {"BottomCenter", 1}, {"Center", 1},
    {"center", 1},     {"BottomRight", 2}, {"Right", 2},     {"right", 2},        {"TopLeft", 3},
    {"TopCenter", 4},  {"TopRight", 5},    {"CenterLeft", 6}, {"CenterCenter", 7}, {"CenterRight", 8},
};

// Gmsh's size when none is given: its default OpenGL font size in batch mode
// (General.FontSize does not change it there; measured with `gmsh -0`).
constexpr int kDefaultFontSize = 15;

std::string choices_of_fonts() {
  std::string out;
  for (std::string_view f : kFonts) out += fmt::format("{}'{}'", out.empty() ? "" : ", ", f);
  return out;
}

std::string choices_of_aligns() {
  std::string out;
  for (const Align& a : kAligns)
    if (a.name[0] >= 'A' && a.name[0] <= 'Z') out += fmt::format("{}'{}'", out.empty() ? "" : ", ", a.name);
  return out;
}

// C atoi's reading (leading blanks, a sign, digits, the rest ignored; no
// digits is 0), as Gmsh reads the size, but refusing what an int cannot hold.
int font_size(const std::string& text, int arg) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
    throw BuiltinError{fmt::format("font size '{}' is out of range", text), arg};
  return static_cast<int>(v);
}

}  // namespace

Value f_text_attributes(BuiltinEnv&, const std::vector<Value>& a) {
  // Arguments are strings or string lists, flattened: `TextAttributes(S())`.
  std::vector<std::pair<std::string, int>> items;   // text, argument index
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    const Value& v = a[static_cast<std::size_t>(i)];
    if (!v.is_string()) arg_string(a, i);   // throws: a number
    for (const std::string& s : v.strs()) items.emplace_back(s, i);
  }
  if (items.size() % 2 != 0)
    throw BuiltinError{fmt::format("text attributes come in key, value pairs, but {} strings were given",
                                   items.size())};
  int align = 0, font = 0, size = kDefaultFontSize;
  for (std::size_t k = 0; k < items.size(); k += 2) {
    const std::string& key = items[k].first;
    const std::string& val = items[k + 1].first;
    const int arg = items[k + 1].second;
    if (key == "Font") {
      const auto* it = std::find(std::begin(kFonts), std::end(kFonts), val);
      if (it == std::end(kFonts))
        throw BuiltinError{fmt::format("unknown font '{}': one of {}", val, choices_of_fonts()), arg};
      font = static_cast<int>(it - std::begin(kFonts));
    } else if (key == "FontSize") {
      size = font_size(val, arg);
    } else if (key == "Align") {
      const auto* it =
          std::find_if(std::begin(kAligns), std::end(kAligns), [&](const Align& x) { return x.name == val; });
      if (it == std::end(kAligns))
        throw BuiltinError{fmt::format("unknown alignment '{}': one of {}", val, choices_of_aligns()), arg};
      align = it->code;
    } else {
      // Gmsh ignores other keys; a misspelt one would silently do nothing.
      throw BuiltinError{fmt::format("unknown text attribute '{}': 'Font', 'FontSize' or 'Align'", key),
                         items[k].second};
    }
  }
  // Gmsh's int arithmetic: a negative or large size spills into the other fields.
  const std::uint32_t packed = (static_cast<std::uint32_t>(align) << 16) | (static_cast<std::uint32_t>(font) << 8) |
                               static_cast<std::uint32_t>(size);
  return Value::number(static_cast<double>(static_cast<std::int32_t>(packed)));
}

}  // namespace sm::interp
