// The built-in functions as the parser sees them: one row per name of
// lang/builtin_functions.def, with what the grammar decides from the name
// (a call, a string-valued call, a call with ONELAB attributes).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace sm::lang {

/// One value per row of builtin_functions.def, in the table's (name) order.
enum class BuiltinId : std::uint16_t {
#define BUILTIN(name, ...) name,
#define MODEL_BUILTIN(name, ...) name,
#include "lang/builtin_functions.def"
#undef BUILTIN
#undef MODEL_BUILTIN
  kNone,
};

/// The group a builtin is listed under in docs/interpreter.md.
enum class BuiltinFamily : std::uint8_t { Math, Lists, Strings, Names, Files, Parameters, Fields };
/// Num: a number or a list of numbers; Str: a string or a string list.
enum class BuiltinResult : std::uint8_t { Num, Str };
/// How the call's arguments reach the function (see builtin_functions.def).
enum class BuiltinPass : std::uint8_t { Values, Lists, Strings, Name, Onelab, Model };

struct BuiltinFunction {
  std::string_view name;
  BuiltinFamily family;
  BuiltinResult result;
  int min_args;
  int max_args;   ///< -1: any number
  BuiltinPass pass;
  std::string_view help;
};

/// Every builtin, sorted by name; index i is BuiltinId i.
std::span<const BuiltinFunction> builtin_functions();
/// The row of `id` (which must not be kNone).
const BuiltinFunction& builtin_function(BuiltinId id);
/// The builtin called `name` (case-sensitive), or BuiltinId::kNone.
BuiltinId find_builtin_function(std::string_view name);

/// The "## Builtins" reference of docs/interpreter.md, generated from the table.
std::string builtin_functions_markdown();

}  // namespace sm::lang
