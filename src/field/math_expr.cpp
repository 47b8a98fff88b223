// MathEval compiler and evaluator. Grammar (MathEx, docs/fields.md):
//   expr   := term(sign) { ("+" | "-") term }
//   term   := power { ("*" | "/" | "%") power }
//   power  := factor [ "^" factor ]            ('^' is not associative)
//   factor := [sign, only first in an expr] ( number | name | name "(" args ")" | "(" expr ")" )
// A sign binds tighter than '^' (-x^2 = (-x)^2) and may not follow an
// operator (2*-x is an error), as in MathEx. Every node gets its own register
// (SSA); constant subtrees are folded at compile time.
#include "field/math_expr.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include <fmt/format.h>

#include "field/error.h"

namespace sm::field {

namespace {

struct FuncInfo {
  const char* name;
  MathExpr::Op op;
  int arity;  ///< -1: variadic (at least one), 0: none
};

constexpr FuncInfo kFuncs[] = {
    {"abs", MathExpr::Op::Abs, 1},     {"fabs", MathExpr::Op::Abs, 1},
    {"acos", MathExpr::Op::Acos, 1},   {"asin", MathExpr::Op::Asin, 1},
    {"atan", MathExpr::Op::Atan, 1},   {"cos", MathExpr::Op::Cos, 1},
    {"cosh", MathExpr::Op::Cosh, 1},   {"exp", MathExpr::Op::Exp, 1},
    {"log", MathExpr::Op::Log, 1},     {"log10", MathExpr::Op::Log10, 1},
    {"sin", MathExpr::Op::Sin, 1},     {"sinh", MathExpr::Op::Sinh, 1},
    {"sqrt", MathExpr::Op::Sqrt, 1},   {"tan", MathExpr::Op::Tan, 1},
    {"tanh", MathExpr::Op::Tanh, 1},   {"atanh", MathExpr::Op::Atanh, 1},
    {"floor", MathExpr::Op::Floor, 1}, {"ceil", MathExpr::Op::Ceil, 1},
    {"round", MathExpr::Op::Round, 1}, {"trunc", MathExpr::Op::Trunc, 1},
    {"sign", MathExpr::Op::Sign, 1},   {"step", MathExpr::Op::Step, 1},
    {"deg", MathExpr::Op::Deg, 1},     {"rad", MathExpr::Op::Rad, 1},
    {"fac", MathExpr::Op::Fac, 1},     {"min", MathExpr::Op::Min, -1},
    {"max", MathExpr::Op::Max, -1},    {"sum", MathExpr::Op::Sum, -1},
    {"med", MathExpr::Op::Med, -1},    {"rand", MathExpr::Op::Rand, 0},
};

/// MathEx accepts a function name in lowercase or Capitalised.
const FuncInfo* find_func(std::string_view name) {
  for (const FuncInfo& f : kFuncs) {
    const std::string_view n = f.name;
    if (name.size() != n.size()) continue;
    if (name == n) return &f;
    if (std::toupper(static_cast<unsigned char>(n[0])) == name[0] && name.substr(1) == n.substr(1))
      return &f;
  }
  return nullptr;
}

double factorial(double x) {
  if (!(x >= 0)) return std::nan("");
  return std::tgamma(std::floor(x) + 1);
}

double median(std::vector<double>& v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// rand(): a deterministic pseudo-random value in [0,1) from the point's
/// coordinates, so meshes are reproducible and evaluation is thread-safe.
double point_random(const Vec3& p) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (double c : {p.x, p.y, p.z}) {
    std::uint64_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
  }
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

double apply1(MathExpr::Op op, double a) {
  using Op = MathExpr::Op;
  switch (op) {
    case Op::Neg: return -a;
    case Op::Abs: return std::fabs(a);
    case Op::Acos: return std::acos(a);
    case Op::Asin: return std::asin(a);
    case Op::Atan: return std::atan(a);
    case Op::Cos: return std::cos(a);
    case Op::Cosh: return std::cosh(a);
    case Op::Exp: return std::exp(a);
    case Op::Log: return std::log(a);
    case Op::Log10: return std::log10(a);
    case Op::Sin: return std::sin(a);
    case Op::Sinh: return std::sinh(a);
    case Op::Sqrt: return std::sqrt(a);
    case Op::Tan: return std::tan(a);
    case Op::Tanh: return std::tanh(a);
    case Op::Atanh: return std::atanh(a);
    case Op::Floor: return std::floor(a);
    case Op::Ceil: return std::ceil(a);
    case Op::Round: return std::floor(a + 0.5);
    case Op::Trunc: return std::trunc(a);
    case Op::Sign: return a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0;
    case Op::Step: return a < 0 ? 0.0 : 1.0;
    case Op::Deg: return a * (180 / std::numbers::pi);
    case Op::Rad: return a * (std::numbers::pi / 180);
    case Op::Fac: return factorial(a);
    default: return std::nan("");
  }
}

double apply2(MathExpr::Op op, double a, double b) {
  using Op = MathExpr::Op;
  switch (op) {
    case Op::Add: return a + b;
    case Op::Sub: return a - b;
    case Op::Mul: return a * b;
    case Op::Div: return a / b;
    case Op::Mod: return std::fmod(a, b);
    case Op::Pow: return std::pow(a, b);
    default: return std::nan("");
  }
}

bool is_unary(MathExpr::Op op) {
  using Op = MathExpr::Op;
  return op == Op::Neg || (op >= Op::Abs && op <= Op::Fac);
}

bool is_variadic(MathExpr::Op op) {
  using Op = MathExpr::Op;
  return op == Op::Min || op == Op::Max || op == Op::Sum || op == Op::Med;
}

}  // namespace

class MathParser {
 public:
  MathParser(std::string_view text, bool allow_fields) : s_(text), allow_fields_(allow_fields) {}

  MathExpr run() {
    skip_ws();
    if (pos_ >= s_.size()) fail(pos_, "empty expression");
    const int r = parse_expr();
    skip_ws();
    if (pos_ < s_.size()) {
      if (s_[pos_] == '^') fail(pos_, "'^' is not associative in MathEval: add parentheses");
      if (s_[pos_] == ')') fail(pos_, "unmatched ')'");
      fail(pos_, fmt::format("unexpected '{}'", s_[pos_]));
    }
    e_.result_ = r;
    return std::move(e_);
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    FieldError e(FieldErrc::ParseError,
                 fmt::format("MathEval expression \"{}\", column {}: {}", s_, at + 1, what));
    e.column = static_cast<int>(at) + 1;
    e.expression = std::string(s_);
    e.reason = what;
    throw e;
  }

  void skip_ws() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }

  bool peek(char c) {
    skip_ws();
    return pos_ < s_.size() && s_[pos_] == c;
  }

  int new_reg(bool is_const, double value) {
    e_.is_const_.push_back(is_const);
    e_.consts_.push_back(value);
    return static_cast<int>(e_.is_const_.size()) - 1;
  }

  int constant(double v) { return new_reg(true, v); }

  bool is_const(int r) const { return e_.is_const_[static_cast<std::size_t>(r)] != 0; }
  double cval(int r) const { return e_.consts_[static_cast<std::size_t>(r)]; }

  int emit(MathExpr::Op op, int a, int b = 0) {
    if (is_unary(op) && is_const(a)) return constant(apply1(op, cval(a)));
    // x^2 is x*x (what a compiler does with std::pow(x, 2)).
    if (op == MathExpr::Op::Pow && !is_const(a) && is_const(b) && cval(b) == 2)
      op = MathExpr::Op::Mul, b = a;
    if (!is_unary(op) && !is_variadic(op) && op >= MathExpr::Op::Add && op <= MathExpr::Op::Pow &&
        is_const(a) && is_const(b))
      return constant(apply2(op, cval(a), cval(b)));
    const int dst = new_reg(false, 0);
    e_.code_.push_back({op, dst, a, b});
    return dst;
  }

  // A sign may only start an expression: after it, any operator followed by
  // a sign is MathEx's "2*-x" error.
  void no_sign_here() {
    if (peek('-') || peek('+'))
      fail(pos_, "a sign cannot follow an operator in MathEval: write 2*(-x), not 2*-x");
  }

  int parse_expr() {
    int r = parse_term(true);
    while (true) {
      skip_ws();
      if (pos_ >= s_.size() || (s_[pos_] != '+' && s_[pos_] != '-')) return r;
      const char op = s_[pos_++];
      no_sign_here();
      const int b = parse_term(false);
      r = emit(op == '+' ? MathExpr::Op::Add : MathExpr::Op::Sub, r, b);
    }
  }

  int parse_term(bool allow_sign) {
    int r = parse_power(allow_sign);
    while (true) {
      skip_ws();
      if (pos_ >= s_.size() || (s_[pos_] != '*' && s_[pos_] != '/' && s_[pos_] != '%')) return r;
      const char op = s_[pos_++];
      no_sign_here();
      const int b = parse_power(false);
      r = emit(op == '*' ? MathExpr::Op::Mul : op == '/' ? MathExpr::Op::Div : MathExpr::Op::Mod, r, b);
    }
  }

  int parse_power(bool allow_sign) {
    const int a = parse_factor(allow_sign);
    if (!peek('^')) return a;
    ++pos_;
    no_sign_here();
    const int b = parse_factor(false);
    if (peek('^')) fail(pos_, "'^' is not associative in MathEval: add parentheses");
    return emit(MathExpr::Op::Pow, a, b);
  }

  int parse_factor(bool allow_sign) {
    skip_ws();
    if (pos_ >= s_.size()) fail(pos_, "expression ends where a value was expected");
    const char c = s_[pos_];
    if (c == '-' || c == '+') {
      if (!allow_sign) fail(pos_, "a sign cannot follow an operator in MathEval: write 2*(-x), not 2*-x");
      ++pos_;
      no_sign_here();
      const int a = parse_factor(false);
      return c == '-' ? emit(MathExpr::Op::Neg, a) : a;
    }
    if (c == '(') {
      const std::size_t open = pos_++;
      const int r = parse_expr();
      if (!peek(')')) fail(pos_, "missing ')' to close '(' at column " +
                                                                  std::to_string(open + 1));
      ++pos_;
      return r;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return parse_number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return parse_name();
    fail(pos_, fmt::format("unexpected '{}' where a value was expected", c));
  }

  int parse_number() {
    const std::size_t start = pos_;
    auto digits = [&] {
      std::size_t n = 0;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_, ++n;
      return n;
    };
    std::size_t n = digits();
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      n += digits();
    }
    if (n == 0) fail(start, "malformed number");
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      std::size_t p = pos_ + 1;
      if (p < s_.size() && (s_[p] == '+' || s_[p] == '-')) ++p;
      if (p < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p]))) {
        pos_ = p;
        digits();
      }
    }
    return constant(std::strtod(std::string(s_.substr(start, pos_ - start)).c_str(), nullptr));
  }

  int parse_name() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() &&
           (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
      ++pos_;
    const std::string_view name = s_.substr(start, pos_ - start);
    if (peek('(')) return parse_call(name, start);
    if (name == "x") return emit(MathExpr::Op::X, 0);
    if (name == "y") return emit(MathExpr::Op::Y, 0);
    if (name == "z") return emit(MathExpr::Op::Z, 0);
    if (name == "Pi" || name == "pi") return constant(std::numbers::pi);
    if (name == "e") return constant(std::numbers::e);
    if (name.size() > 1 && name[0] == 'F' &&
        std::all_of(name.begin() + 1, name.end(), [](char d) { return std::isdigit(static_cast<unsigned char>(d)); })) {
      if (!allow_fields_) fail(start, fmt::format("field reference '{}' is not allowed here", name));
      const int id = std::stoi(std::string(name.substr(1)));
      auto it = std::find(e_.refs_.begin(), e_.refs_.end(), id);
      const int k = static_cast<int>(it - e_.refs_.begin());
      if (it == e_.refs_.end()) e_.refs_.push_back(id);
      return emit(MathExpr::Op::Field, k);
    }
    if (find_func(name)) fail(start, fmt::format("function '{}' needs its arguments in parentheses", name));
    fail(start, fmt::format("unknown name '{}' (MathEval knows x, y, z, F<n>, Pi, e and its "
                            "functions; there is no atan2 or hypot)", name));
  }

  int parse_call(std::string_view name, std::size_t start) {
    const FuncInfo* f = find_func(name);
    if (!f) fail(start, fmt::format("unknown function '{}'", name));
    ++pos_;  // '('
    std::vector<int> args;
    if (!peek(')')) {
      while (true) {
        args.push_back(parse_expr());
        if (peek(',')) {
          ++pos_;
          continue;
        }
        break;
      }
    }
    if (!peek(')')) fail(pos_, fmt::format("missing ')' after the arguments of '{}'", name));
    ++pos_;
    const int n = static_cast<int>(args.size());
    if (f->arity >= 0 && n != f->arity)
      fail(start, fmt::format("function '{}' takes {} argument{}, got {}", name, f->arity,
                              f->arity == 1 ? "" : "s", n));
    if (f->arity < 0 && n == 0) fail(start, fmt::format("function '{}' needs at least one argument", name));
    if (f->arity == 1) return emit(f->op, args[0]);
    if (f->arity == 0) return emit(f->op, 0);
    const int first = static_cast<int>(e_.args_.size());
    e_.args_.insert(e_.args_.end(), args.begin(), args.end());
    const int dst = new_reg(false, 0);
    e_.code_.push_back({f->op, dst, first, n});
    return dst;
  }

  std::string_view s_;
  bool allow_fields_;
  std::size_t pos_ = 0;
  MathExpr e_;
};

MathExpr MathExpr::compile(std::string_view text, bool allow_fields) {
  return MathParser(text, allow_fields).run();
}

void MathExpr::eval(std::span<const Vec3> pts, std::span<const std::span<const double>> fields,
                    std::span<double> out) const {
  constexpr std::size_t kChunk = 256;
  const std::size_t nreg = is_const_.size();
  // Register r of the current chunk lives at reg[r * kChunk ...]; constant
  // registers are filled once and never written again (SSA).
  std::vector<double> reg(nreg * kChunk);
  for (std::size_t r = 0; r < nreg; ++r)
    if (is_const_[r]) std::fill_n(&reg[r * kChunk], kChunk, consts_[r]);
  std::vector<double> scratch;
  for (std::size_t base = 0; base < pts.size(); base += kChunk) {
    const std::size_t n = std::min(kChunk, pts.size() - base);
    for (const Instr& ins : code_) {
      double* d = &reg[static_cast<std::size_t>(ins.dst) * kChunk];
      const double* a = &reg[static_cast<std::size_t>(ins.a) * kChunk];
      const double* b = &reg[static_cast<std::size_t>(ins.b) * kChunk];
      switch (ins.op) {
        case Op::X: for (std::size_t i = 0; i < n; ++i) d[i] = pts[base + i].x; break;
        case Op::Y: for (std::size_t i = 0; i < n; ++i) d[i] = pts[base + i].y; break;
        case Op::Z: for (std::size_t i = 0; i < n; ++i) d[i] = pts[base + i].z; break;
        case Op::Field: {
          const double* f = fields[static_cast<std::size_t>(ins.a)].data() + base;
          std::copy_n(f, n, d);
          break;
        }
        case Op::Add: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] + b[i]; break;
        case Op::Sub: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] - b[i]; break;
        case Op::Mul: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] * b[i]; break;
        case Op::Div: for (std::size_t i = 0; i < n; ++i) d[i] = a[i] / b[i]; break;
        case Op::Mod: for (std::size_t i = 0; i < n; ++i) d[i] = std::fmod(a[i], b[i]); break;
        case Op::Pow: for (std::size_t i = 0; i < n; ++i) d[i] = std::pow(a[i], b[i]); break;
        case Op::Neg: for (std::size_t i = 0; i < n; ++i) d[i] = -a[i]; break;
        case Op::Sqrt: for (std::size_t i = 0; i < n; ++i) d[i] = std::sqrt(a[i]); break;
        case Op::Abs: for (std::size_t i = 0; i < n; ++i) d[i] = std::fabs(a[i]); break;
        case Op::Sin: for (std::size_t i = 0; i < n; ++i) d[i] = std::sin(a[i]); break;
        case Op::Cos: for (std::size_t i = 0; i < n; ++i) d[i] = std::cos(a[i]); break;
        case Op::Exp: for (std::size_t i = 0; i < n; ++i) d[i] = std::exp(a[i]); break;
        case Op::Rand: for (std::size_t i = 0; i < n; ++i) d[i] = point_random(pts[base + i]); break;
        case Op::Min: case Op::Max: case Op::Sum: case Op::Med: {
          const int* args = &args_[static_cast<std::size_t>(ins.a)];
          const std::size_t na = static_cast<std::size_t>(ins.b);
          for (std::size_t i = 0; i < n; ++i) {
            scratch.clear();
            for (std::size_t k = 0; k < na; ++k)
              scratch.push_back(reg[static_cast<std::size_t>(args[k]) * kChunk + i]);
            double v;
            if (ins.op == Op::Min) v = *std::min_element(scratch.begin(), scratch.end());
            else if (ins.op == Op::Max) v = *std::max_element(scratch.begin(), scratch.end());
            else if (ins.op == Op::Sum) { v = 0; for (double s : scratch) v += s; }
            else v = median(scratch);
            d[i] = v;
          }
          break;
        }
        default: for (std::size_t i = 0; i < n; ++i) d[i] = apply1(ins.op, a[i]); break;
      }
    }
    const double* r = &reg[static_cast<std::size_t>(result_) * kChunk];
    std::copy_n(r, n, out.data() + base);
  }
}

}  // namespace sm::field
