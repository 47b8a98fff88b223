// The builtins' implementation table, shared argument helpers and the
// predefined constants.
#include "interp/builtins/builtins.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

#include <fmt/format.h>

namespace sm::interp {
namespace {

constexpr BuiltinFn kImpl[] = {
#define BUILTIN(name, family, result, lo, hi, pass, impl, help) &impl,
#define MODEL_BUILTIN(name, family, result, lo, hi, help) nullptr,
#include "lang/builtin_functions.def"
#undef BUILTIN
#undef MODEL_BUILTIN
};
static_assert(std::size(kImpl) == static_cast<std::size_t>(lang::BuiltinId::kNone));

}  // namespace

BuiltinFn builtin_impl(lang::BuiltinId id) { return kImpl[static_cast<std::size_t>(id)]; }

BuiltinFn find_builtin(std::string_view name) {
  const lang::BuiltinId id = lang::find_builtin_function(name);
  return id == lang::BuiltinId::kNone ? nullptr : builtin_impl(id);
}

const Limits& env_limits(const BuiltinEnv& env) {
  static const Limits kDefaults;
  return env.limits ? *env.limits : kDefaults;
}

double arg_number(const std::vector<Value>& args, int i) {
  const Value& v = args[static_cast<std::size_t>(i)];
  if (!v.is_numeric())
    throw BuiltinError{fmt::format("argument {} must be a number, not {}", i + 1, kind_phrase(v)), i};
  if (v.nums().empty()) throw BuiltinError{fmt::format("argument {} is an empty list", i + 1), i};
  return v.nums()[0];   // Gmsh: a list used as a scalar is its element 0
}

std::string arg_string(const std::vector<Value>& args, int i) {
  const Value& v = args[static_cast<std::size_t>(i)];
  if (!v.is_string())
    throw BuiltinError{fmt::format("argument {} must be a string, not {}", i + 1, kind_phrase(v)), i};
  return join_lines(v.strs());
}

const std::vector<double>& arg_list(const std::vector<Value>& args, int i) {
  const Value& v = args[static_cast<std::size_t>(i)];
  if (!v.is_numeric())
    throw BuiltinError{fmt::format("argument {} must be a list of numbers, not {}", i + 1, kind_phrase(v)), i};
  return v.nums();
}

std::string script_relative_path(const BuiltinEnv& env, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  if (p.is_absolute() || env.script_path.empty()) return path;
  return (fs::path(env.script_path).parent_path() / p).lexically_normal().string();
}

std::string resolve_script_path(const BuiltinEnv& env, const std::string& path) {
  std::string resolved = script_relative_path(env, path);
  if (env.redirects && !env.redirects->empty()) env.redirects->publish(resolved);
  return resolved;
}

bool builtin_number_constant(std::string_view name, double& out) {
  // Gmsh reports its own version; scripts test GMSH_MAJOR_VERSION >= 4 to pick
  // the 4.x syntax, so we answer as the 4.8.4 we are compatible with.
  static const std::pair<std::string_view, double> kConstants[] = {
      {"Pi", 3.14159265358979323846},
      {"GMSH_MAJOR_VERSION", 4},
      {"GMSH_MINOR_VERSION", 8},
      {"GMSH_PATCH_VERSION", 4},
      {"MPI_Size", 1},
      {"MPI_Rank", 0},
  };
  for (const auto& [n, v] : kConstants) {
    if (n == name) {
      out = v;
      return true;
    }
  }
  if (name == "Cpu") {
    out = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
    return true;
  }
  if (name == "Memory" || name == "TotalMemory") {
    out = 0;   // not measured: documented in docs/interpreter.md
    return true;
  }
  return false;
}

std::string gmsh_today(const std::tm& local) {
  char buf[64];
  std::strftime(buf, sizeof buf, "%a %b %e %H:%M:%S %Y", &local);
  return buf;
}

bool builtin_string_constant(std::string_view name, const BuiltinEnv& env, std::string& out) {
  namespace fs = std::filesystem;
  if (name == "Today") {
    const std::time_t now = std::time(nullptr);
    out = gmsh_today(*std::localtime(&now));
    return true;
  }
  if (name == "CurrentDirectory" || name == "CurrentDir") {
    // Gmsh: the directory of the script being parsed, with a trailing slash.
    std::string dir = env.script_path.empty()
                          ? fs::current_path().string()
                          : fs::absolute(fs::path(env.script_path)).parent_path().string();
    if (dir.empty() || dir.back() != '/') dir += '/';
    out = dir;
    return true;
  }
  if (name == "CurrentFileName") {
    out = fs::path(env.script_path).filename().string();
    return true;
  }
  if (name == "GmshExecutableName") {
    out = "stereomesh";
    return true;
  }
  if (name == "OnelabAction") {
    out = "";
    return true;
  }
  return false;
}

}  // namespace sm::interp
