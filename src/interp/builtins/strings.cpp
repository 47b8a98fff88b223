// String builtins of the Gmsh 4.8.4 manual (§4.2.2 char-expression), the
// numeric ones that read strings (StrLen, StrCmp, StrFind, FileExists,
// GetNumber, GetValue) and the ONELAB-style parameters.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "interp/builtins/builtins.h"
#include "interp/format.h"
#include "interp/limits.h"

namespace sm::interp {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void too_long(const BuiltinEnv& env, std::size_t size) {
  throw BuiltinError{fmt::format("string of {} bytes is longer than the limit of {}", size,
                                 env_limits(env).max_string_size)};
}

Value checked_string(const BuiltinEnv& env, std::string s) {
  if (s.size() > env_limits(env).max_string_size) too_long(env, s.size());
  return Value::string(std::move(s));
}
}  // namespace

Value f_strcat(BuiltinEnv& env, const std::vector<Value>& a) {
  std::string s;
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    s += arg_string(a, i);
    if (s.size() > env_limits(env).max_string_size) too_long(env, s.size());
  }
  return Value::string(std::move(s));
}

// Str makes a string list: `S[] = Str("a", "b")` has two elements, while
// `s = Str("a", "b")` joins them with newlines (Gmsh's multi-line strings).
Value f_str(BuiltinEnv& env, const std::vector<Value>& a) {
  std::vector<std::string> out;
  std::size_t total = 0;
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    out.push_back(arg_string(a, i));
    total += out.back().size() + 1;
    if (total > env_limits(env).max_string_size) too_long(env, total);
  }
  return Value::string_list(std::move(out));
}

Value f_sprintf(BuiltinEnv& env, const std::vector<Value>& a) {
  const std::string& f = arg_string(a, 0);
  std::vector<FormatArg> args;
  std::vector<int> origin;   // argument index of each flattened item
  for (int i = 1; i < static_cast<int>(a.size()); ++i) {
    const Value& v = a[static_cast<std::size_t>(i)];
    if (v.is_numeric())
      for (double x : v.nums()) args.emplace_back(x), origin.push_back(i);
    else
      for (const auto& s : v.strs()) args.emplace_back(s), origin.push_back(i);
  }
  FormatResult r = format_gmsh(f, args);
  if (!r.ok)
    throw BuiltinError{r.error, r.arg_index >= 0 && r.arg_index < static_cast<int>(origin.size())
                                    ? origin[static_cast<std::size_t>(r.arg_index)]
                                    : 0};
  return checked_string(env, std::move(r.text));
}

Value f_strlen(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(static_cast<double>(arg_string(a, 0).size()));
}

// The sign of C strcmp.
Value f_strcmp(BuiltinEnv&, const std::vector<Value>& a) {
  const int c = std::strcmp(arg_string(a, 0).c_str(), arg_string(a, 1).c_str());
  return Value::number(c < 0 ? -1 : (c > 0 ? 1 : 0));
}

Value f_strfind(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(arg_string(a, 0).find(arg_string(a, 1)) != std::string::npos ? 1 : 0);
}

// Removes the extension: "dir/file.geo" -> "dir/file".
Value f_strprefix(BuiltinEnv&, const std::vector<Value>& a) {
  const std::string& s = arg_string(a, 0);
  const std::size_t dot = s.find_last_of('.');
  const std::size_t slash = s.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return Value::string(s);
  return Value::string(s.substr(0, dot));
}

// Removes the directory: "dir/file.geo" -> "file.geo".
Value f_strrelative(BuiltinEnv&, const std::vector<Value>& a) {
  const std::string& s = arg_string(a, 0);
  const std::size_t slash = s.find_last_of("/\\");
  return Value::string(slash == std::string::npos ? s : s.substr(slash + 1));
}

// StrSub(s, i, n): n characters from index i (to the end without n).
Value f_strsub(BuiltinEnv&, const std::vector<Value>& a) {
  const std::string& s = arg_string(a, 0);
  const double i = std::trunc(arg_number(a, 1));
  if (!(i >= 0) || i > static_cast<double>(s.size()))
    throw BuiltinError{fmt::format("start index {} is outside the string of length {}", i, s.size()), 1};
  std::size_t n = std::string::npos;
  if (a.size() > 2) {
    const double dn = std::trunc(arg_number(a, 2));
    if (!(dn >= 0)) throw BuiltinError{fmt::format("length {} is negative", dn), 2};
    if (dn < static_cast<double>(s.size())) n = static_cast<std::size_t>(dn);
  }
  return Value::string(s.substr(static_cast<std::size_t>(i), n));
}

Value f_strreplace(BuiltinEnv& env, const std::vector<Value>& a) {
  std::string s = arg_string(a, 0);
  const std::string& from = arg_string(a, 1);
  const std::string& to = arg_string(a, 2);
  if (from.empty()) throw BuiltinError{"the string to replace is empty", 1};
  std::string out;
  std::size_t pos = 0;
  for (std::size_t hit; (hit = s.find(from, pos)) != std::string::npos; pos = hit + from.size()) {
    out.append(s, pos, hit - pos);
    out += to;
    if (out.size() > env_limits(env).max_string_size) too_long(env, out.size());
  }
  out.append(s, pos, std::string::npos);
  return checked_string(env, std::move(out));
}

Value f_uppercase(BuiltinEnv&, const std::vector<Value>& a) {
  std::string s = arg_string(a, 0);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return Value::string(std::move(s));
}

Value f_strchoice(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::string(arg_number(a, 0) != 0 ? arg_string(a, 1) : arg_string(a, 2));
}

Value f_absolutepath(BuiltinEnv& env, const std::vector<Value>& a) {
  return Value::string(fs::absolute(fs::path(resolve_script_path(env, arg_string(a, 0))))
                           .lexically_normal()
                           .string());
}

// Everything up to and including the last '/': "/a/b/c.geo" -> "/a/b/".
Value f_dirname(BuiltinEnv&, const std::vector<Value>& a) {
  const std::string& s = arg_string(a, 0);
  const std::size_t slash = s.find_last_of("/\\");
  return Value::string(slash == std::string::npos ? std::string() : s.substr(0, slash + 1));
}

Value f_getenv(BuiltinEnv&, const std::vector<Value>& a) {
  const char* v = std::getenv(arg_string(a, 0).c_str());
  return Value::string(v ? v : "");
}

Value f_fileexists(BuiltinEnv& env, const std::vector<Value>& a) {
  std::error_code ec;
  return Value::number(fs::exists(resolve_script_path(env, arg_string(a, 0)), ec) ? 1 : 0);
}

// Batch mode: the default, without asking (Gmsh also prints the prompt).
Value f_getvalue(BuiltinEnv&, const std::vector<Value>& a) {
  arg_string(a, 0);
  return Value::number(arg_number(a, 1));
}

Value f_getnumber(BuiltinEnv& env, const std::vector<Value>& a) {
  const std::string& name = arg_string(a, 0);
  if (auto it = env.onelab_numbers.find(name); it != env.onelab_numbers.end())
    return Value::number(it->second);
  if (a.size() > 1) return Value::number(arg_number(a, 1));
  throw BuiltinError{fmt::format("no parameter '{}' was set with SetNumber or DefineNumber; "
                                 "give a default as second argument", name), 0};
}

Value f_getstring(BuiltinEnv& env, const std::vector<Value>& a) {
  const std::string& name = arg_string(a, 0);
  if (auto it = env.onelab_strings.find(name); it != env.onelab_strings.end())
    return Value::string(it->second);
  if (a.size() > 1) return Value::string(arg_string(a, 1));
  throw BuiltinError{fmt::format("no parameter '{}' was set with SetString or DefineString; "
                                 "give a default as second argument", name), 0};
}

Value f_getstringvalue(BuiltinEnv&, const std::vector<Value>& a) {
  arg_string(a, 0);
  return Value::string(arg_string(a, 1));
}

// DefineNumber/DefineString: ONELAB would offer the value in its GUI; a
// batch run takes it as given (the parser dropped the attributes).
Value f_define_parameter(BuiltinEnv&, const std::vector<Value>& a) { return a[0]; }

Value f_setnumber(BuiltinEnv& env, const std::vector<Value>& a) {
  const double v = arg_number(a, 1);
  env.onelab_numbers[arg_string(a, 0)] = v;
  return Value::number(v);
}

Value f_setstring(BuiltinEnv& env, const std::vector<Value>& a) {
  const std::string& v = arg_string(a, 1);
  env.onelab_strings[arg_string(a, 0)] = v;
  return Value::string(v);
}

}  // namespace sm::interp
