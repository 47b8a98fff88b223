// Built-in functions callable from expressions (`Sqrt(x)`, `StrCat(a,b)`,
// `LinSpace[0,1,5]`...), one family per file; the rows of
// lang/builtin_functions.def name them, and the evaluator calls them with the
// arguments the row asks for.
#pragma once

#include <cstdint>
#include <ctime>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "interp/limits.h"
#include "interp/options.h"
#include "interp/redirect_files.h"
#include "interp/value.h"
#include "lang/builtin_function.h"

namespace sm::interp {

/// What a builtin may touch: the run's variables, options, ONELAB-style
/// parameters, the directory of the script being run, and a seeded generator.
struct BuiltinEnv {
  Symbols& symbols;
  Options& options;
  std::map<std::string, double, std::less<>>& onelab_numbers;
  std::map<std::string, std::string, std::less<>>& onelab_strings;
  std::string script_path;   ///< file of the statement being run ("" for none)
  std::uint64_t& rand_state;
  const Limits* limits = nullptr;   ///< nullptr: the defaults
  /// The run's Printf > files: a file the script wrote is put in place before
  /// a builtin reads it (nullptr: none).
  RedirectFiles* redirects = nullptr;
};

/// The run's limits (the defaults when the environment names none).
const Limits& env_limits(const BuiltinEnv& env);

/// A builtin's failure: a message about the call, or about argument `arg`.
struct BuiltinError {
  std::string message;
  int arg = -1;
};

using BuiltinFn = Value (*)(BuiltinEnv& env, const std::vector<Value>& args);

// The implementations named by lang/builtin_functions.def, one family per file
// (math.cpp, lists.cpp, strings.cpp, names.cpp, text_attributes.cpp). They get the arguments the
// table's BuiltinPass describes, already checked against its arity.
#define BUILTIN(name, family, result, lo, hi, pass, impl, help) \
  Value impl(BuiltinEnv& env, const std::vector<Value>& args);
#define MODEL_BUILTIN(name, family, result, lo, hi, help)
#include "lang/builtin_functions.def"
#undef BUILTIN
#undef MODEL_BUILTIN

/// The implementation of `id`, or nullptr for a MODEL_BUILTIN (the evaluator
/// runs those through eval_field_call, kernel/dispatch.h).
BuiltinFn builtin_impl(lang::BuiltinId id);
/// The implementation of the builtin called `name`, or nullptr.
BuiltinFn find_builtin(std::string_view name);

/// `Today` for a given local time, as Gmsh prints it (C's ctime layout: the day of the
/// month padded with a space, "Wed Dec  2 12:05:03 2026").
std::string gmsh_today(const std::tm& local);

/// The string constants `Today`, `CurrentDirectory`... or false when `name` is none.
bool builtin_string_constant(std::string_view name, const BuiltinEnv& env, std::string& out);
/// The numeric constants `Pi`, `GMSH_MAJOR_VERSION`, `MPI_Size`, ... or false.
bool builtin_number_constant(std::string_view name, double& out);

// Argument helpers shared by the family files; they throw BuiltinError.
double arg_number(const std::vector<Value>& args, int i);
std::string arg_string(const std::vector<Value>& args, int i);
/// A numeric argument as a list (a scalar is a one-element list).
const std::vector<double>& arg_list(const std::vector<Value>& args, int i);
/// Resolves a script-relative path against the running script's directory, for
/// reading: a file this run wrote with Printf > is put in place first.
std::string resolve_script_path(const BuiltinEnv& env, const std::string& path);
/// The same path for writing (Printf >): nothing is put in place.
std::string script_relative_path(const BuiltinEnv& env, const std::string& path);

}  // namespace sm::interp
