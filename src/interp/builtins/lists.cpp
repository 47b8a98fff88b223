// List builtins of the Gmsh 4.8.4 manual (§4.2.1 expression-list-item):
// List, Unique, LinSpace, LogSpace, ListFromFile, Find.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "interp/builtins/builtins.h"
#include "base/file_identity.h"
#include "interp/limits.h"

namespace sm::interp {
namespace {

std::size_t checked_count(const BuiltinEnv& env, double n, int arg) {
  const std::size_t max = env_limits(env).max_list_size;
  if (!(n >= 0) || n > static_cast<double>(max))
    throw BuiltinError{fmt::format("list size {} is outside [0, {}]", n, max), arg};
  return static_cast<std::size_t>(n);
}

// n values from a to b, both included (n = 1 gives {a}).
std::vector<double> linspace(double a, double b, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = n == 1 ? a : a + (b - a) * static_cast<double>(i) / static_cast<double>(n - 1);
  return v;
}

}  // namespace

Value f_list(BuiltinEnv&, const std::vector<Value>& a) { return Value::list(arg_list(a, 0)); }

// Sorts and removes duplicates.
Value f_unique(BuiltinEnv&, const std::vector<Value>& a) {
  std::vector<double> v = arg_list(a, 0);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return Value::list(std::move(v));
}

Value f_linspace(BuiltinEnv& env, const std::vector<Value>& a) {
  return Value::list(
      linspace(arg_number(a, 0), arg_number(a, 1), checked_count(env, std::trunc(arg_number(a, 2)), 2)));
}

Value f_logspace(BuiltinEnv& env, const std::vector<Value>& a) {
  std::vector<double> v =
      linspace(arg_number(a, 0), arg_number(a, 1), checked_count(env, std::trunc(arg_number(a, 2)), 2));
  for (double& x : v) x = std::pow(10.0, x);
  return Value::list(std::move(v));
}

// Whitespace-separated numbers; anything else is an error naming the token.
Value f_list_from_file(BuiltinEnv& env, const std::vector<Value>& a) {
  const std::string path = resolve_script_path(env, arg_string(a, 0));
  // Only regular files of bounded size: /dev/zero or a FIFO must not hang us.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw BuiltinError{fmt::format("'{}' is not a readable regular file", path), 0};
  const std::size_t max_bytes = env_limits(env).max_string_size * 4;
  if (std::filesystem::file_size(path, ec) > max_bytes)
    throw BuiltinError{fmt::format("'{}' is larger than {} bytes", path, max_bytes), 0};
  std::ifstream in(path);
  if (!in) throw BuiltinError{fmt::format("cannot open '{}'", path), 0};
  base::note_input_file(path);
  std::vector<double> v;
  std::string tok;
  while (in >> tok) {
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0')
      throw BuiltinError{fmt::format("'{}' in '{}' (item {}) is not a number", tok.substr(0, 40), path,
                                     v.size() + 1), 0};
    if (v.size() >= env_limits(env).max_list_size)
      throw BuiltinError{fmt::format("'{}' holds more than {} numbers", path, env_limits(env).max_list_size), 0};
    v.push_back(x);
  }
  return Value::list(std::move(v));
}

// How many items of the first list occur in the second.
Value f_find(BuiltinEnv&, const std::vector<Value>& a) {
  const std::vector<double>& what = arg_list(a, 0);
  std::vector<double> where = arg_list(a, 1);
  std::sort(where.begin(), where.end());
  double count = 0;
  for (double x : what)
    if (std::binary_search(where.begin(), where.end(), x)) count += 1;
  return Value::number(count);
}

}  // namespace sm::interp
