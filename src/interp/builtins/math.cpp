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

}  // namespace

void add_math_builtins(std::vector<BuiltinInfo>& out) {
  const BuiltinInfo fns[] = {
      {"Sqrt", 1, 1, f_sqrt, "square root (argument >= 0)"},
      {"Exp", 1, 1, f_exp, "e raised to the argument"},
      {"Log", 1, 1, f_log, "natural logarithm (argument > 0)"},
      {"Log10", 1, 1, f_log10, "base-10 logarithm (argument > 0)"},
      {"Sin", 1, 1, f_sin, "sine (radians)"},
      {"Cos", 1, 1, f_cos, "cosine (radians)"},
      {"Tan", 1, 1, f_tan, "tangent (radians)"},
      {"Asin", 1, 1, f_asin, "arc sine, in [-Pi/2,Pi/2]"},
      {"ArcSin", 1, 1, f_asin, "synonym of Asin"},
      {"Acos", 1, 1, f_acos, "arc cosine, in [0,Pi]"},
      {"ArcCos", 1, 1, f_acos, "synonym of Acos"},
      {"Atan", 1, 1, f_atan, "arc tangent, in [-Pi/2,Pi/2]"},
      {"ArcTan", 1, 1, f_atan, "synonym of Atan"},
      {"Atan2", 2, 2, f_atan2, "Atan2(y, x): arc tangent of y/x in [-Pi,Pi]"},
      {"ArcTan2", 2, 2, f_atan2, "synonym of Atan2"},
      {"Sinh", 1, 1, f_sinh, "hyperbolic sine"},
      {"Cosh", 1, 1, f_cosh, "hyperbolic cosine"},
      {"Tanh", 1, 1, f_tanh, "hyperbolic tangent"},
      {"Fabs", 1, 1, f_fabs, "absolute value"},
      {"Abs", 1, 1, f_abs, "absolute value; element by element on a list"},
      {"Floor", 1, 1, f_floor, "round down"},
      {"Ceil", 1, 1, f_ceil, "round up"},
      {"Round", 1, 1, f_round, "floor(x + 0.5): Round(-2.5) = -2"},
      {"Fmod", 2, 2, f_fmod, "remainder with the sign of the first argument"},
      {"Modulo", 2, 2, f_fmod, "synonym of Fmod"},
      {"Hypot", 2, 2, f_hypot, "sqrt(a^2 + b^2)"},
      {"Min", 2, 2, f_min, "smaller of two numbers"},
      {"Max", 2, 2, f_max, "larger of two numbers"},
      {"Rand", 1, 1, f_rand, "uniform random number in [0, argument] (fixed seed)"},
      {"Step", 1, 1, f_step, "0 if the argument is < 0, else 1 (not in Gmsh 4.8.4)"},
  };
  out.insert(out.end(), std::begin(fns), std::end(fns));
}

}  // namespace sm::interp
