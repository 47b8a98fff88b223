// Numeric builtins of the Gmsh 4.8.4 manual (§4.4 Built-in functions) plus
// Step and Abs. Domain errors are script errors here, where Gmsh prints nan.
#include <cmath>

#include <fmt/format.h>

#include "interp/builtins/builtins.h"
#include "interp/format.h"

namespace sm::interp {
namespace {

[[noreturn]] void domain_error(std::string_view fn, double x, std::string_view need) {
  throw BuiltinError{fmt::format("{}({}) is undefined: the argument must be {}", fn, format_g(x), need), 0};
}

double x0(const std::vector<Value>& a) { return arg_number(a, 0); }
double x1(const std::vector<Value>& a) { return arg_number(a, 1); }
}  // namespace

Value f_sqrt(BuiltinEnv&, const std::vector<Value>& a) {
  const double x = x0(a);
  if (x < 0) domain_error("Sqrt", x, ">= 0");
  return Value::number(std::sqrt(x));
}
Value f_exp(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::exp(x0(a))); }
Value f_log(BuiltinEnv&, const std::vector<Value>& a) {
  const double x = x0(a);
  if (!(x > 0)) domain_error("Log", x, "> 0");
  return Value::number(std::log(x));
}
Value f_log10(BuiltinEnv&, const std::vector<Value>& a) {
  const double x = x0(a);
  if (!(x > 0)) domain_error("Log10", x, "> 0");
  return Value::number(std::log10(x));
}
Value f_sin(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::sin(x0(a))); }
Value f_cos(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::cos(x0(a))); }
Value f_tan(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::tan(x0(a))); }
Value f_asin(BuiltinEnv&, const std::vector<Value>& a) {
  const double x = x0(a);
  if (!(x >= -1 && x <= 1)) domain_error("Asin", x, "in [-1,1]");
  return Value::number(std::asin(x));
}
Value f_acos(BuiltinEnv&, const std::vector<Value>& a) {
  const double x = x0(a);
  if (!(x >= -1 && x <= 1)) domain_error("Acos", x, "in [-1,1]");
  return Value::number(std::acos(x));
}
Value f_atan(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::atan(x0(a))); }
Value f_atan2(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(std::atan2(x0(a), x1(a)));
}
Value f_sinh(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::sinh(x0(a))); }
Value f_cosh(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::cosh(x0(a))); }
Value f_tanh(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::tanh(x0(a))); }
Value f_fabs(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::fabs(x0(a))); }
// Abs also works element by element on a list (`Abs[{-1,2}]`).
Value f_abs(BuiltinEnv&, const std::vector<Value>& a) {
  if (a[0].kind() == Value::Kind::List) {
    std::vector<double> out = arg_list(a, 0);
    for (double& x : out) x = std::fabs(x);
    return Value::list(std::move(out));
  }
  return Value::number(std::fabs(x0(a)));
}
Value f_floor(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::floor(x0(a))); }
Value f_ceil(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(std::ceil(x0(a))); }
// Gmsh rounds half up: Round(-2.5) = -2.
Value f_round(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(std::floor(x0(a) + 0.5));
}
Value f_fmod(BuiltinEnv&, const std::vector<Value>& a) {
  const double y = x1(a);
  if (y == 0) throw BuiltinError{"Fmod by zero", 1};
  return Value::number(std::fmod(x0(a), y));
}
Value f_hypot(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(std::hypot(x0(a), x1(a)));
}
Value f_min(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(std::fmin(x0(a), x1(a)));
}
Value f_max(BuiltinEnv&, const std::vector<Value>& a) {
  return Value::number(std::fmax(x0(a), x1(a)));
}
// Rand(a) = a * u with u uniform in [0,1]: a fixed-seed SplitMix64 stream, so
// every run of a script gives the same numbers.
Value f_rand(BuiltinEnv& env, const std::vector<Value>& a) {
  std::uint64_t z = (env.rand_state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  const double u = static_cast<double>(z >> 11) / static_cast<double>(1ull << 53);
  return Value::number(x0(a) * u);
}
Value f_step(BuiltinEnv&, const std::vector<Value>& a) { return Value::number(x0(a) < 0 ? 0 : 1); }

}  // namespace sm::interp
