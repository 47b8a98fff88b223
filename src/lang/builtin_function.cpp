// The builtin-function table of builtin_functions.def, its lookup by name
// and its Markdown rendering for docs/interpreter.md.
#include "lang/builtin_function.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace sm::lang {
namespace {

constexpr BuiltinFunction kFunctions[] = {
#define BUILTIN(name, family, result, lo, hi, pass, impl, help) \
  {#name, BuiltinFamily::family, BuiltinResult::result, lo, hi, BuiltinPass::pass, help},
#define MODEL_BUILTIN(name, family, result, lo, hi, help) \
  {#name, BuiltinFamily::family, BuiltinResult::result, lo, hi, BuiltinPass::Model, help},
#include "lang/builtin_functions.def"
#undef BUILTIN
#undef MODEL_BUILTIN
};

static_assert(std::size(kFunctions) == static_cast<std::size_t>(BuiltinId::kNone));

// Lookup is a binary search: the rows must stay in byte order of their names.
constexpr bool sorted_by_name() {
  for (std::size_t i = 1; i < std::size(kFunctions); ++i)
    if (!(kFunctions[i - 1].name < kFunctions[i].name)) return false;
  return true;
}
static_assert(sorted_by_name(), "builtin_functions.def: rows must be sorted by name, without duplicates");

std::string_view family_title(BuiltinFamily f) {
  switch (f) {
    case BuiltinFamily::Math: return "Math";
    case BuiltinFamily::Lists: return "Lists";
    case BuiltinFamily::Strings: return "Strings";
    case BuiltinFamily::Names: return "Names";
    case BuiltinFamily::Files: return "Files";
    case BuiltinFamily::Parameters: return "Parameters";
    case BuiltinFamily::Fields: return "Size fields";
  }
  return "?";
}

std::string arity_text(const BuiltinFunction& f) {
  if (f.max_args < 0) return f.min_args == 0 ? "any" : fmt::format("{} or more", f.min_args);
  if (f.min_args == f.max_args) return fmt::format("{}", f.min_args);
  if (f.pass == BuiltinPass::Model) return fmt::format("{} or {}", f.min_args, f.max_args);
  return fmt::format("{} to {}", f.min_args, f.max_args);
}

// A '|' inside a table cell would end the cell.
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::span<const BuiltinFunction> builtin_functions() { return kFunctions; }

const BuiltinFunction& builtin_function(BuiltinId id) { return kFunctions[static_cast<std::size_t>(id)]; }

BuiltinId find_builtin_function(std::string_view name) {
  const auto* it = std::lower_bound(std::begin(kFunctions), std::end(kFunctions), name,
                                    [](const BuiltinFunction& f, std::string_view n) { return f.name < n; });
  if (it == std::end(kFunctions) || it->name != name) return BuiltinId::kNone;
  return static_cast<BuiltinId>(it - std::begin(kFunctions));
}

std::string builtin_functions_markdown() {
  constexpr BuiltinFamily kOrder[] = {BuiltinFamily::Math,  BuiltinFamily::Lists,      BuiltinFamily::Strings,
                                      BuiltinFamily::Names, BuiltinFamily::Files,      BuiltinFamily::Parameters,
                                      BuiltinFamily::Fields};
  std::string out;
  for (BuiltinFamily fam : kOrder) {
    out += fmt::format("\n**{}**\n\n| function | arguments | result | meaning |\n|---|---|---|---|\n",
                       family_title(fam));
    for (const BuiltinFunction& f : kFunctions) {
      if (f.family != fam) continue;
      out += fmt::format("| `{}` | {} | {} | {} |\n", f.name, arity_text(f),
                         f.result == BuiltinResult::Str ? "string" : "numeric", cell(f.help));
    }
  }
  return out;
}

}  // namespace sm::lang
