// Gmsh's MathEval expression language (the MathEx syntax of docs/fields.md,
// not the .geo grammar), compiled once into a flat register program that
// is evaluated chunk by chunk over a batch of points.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/vec.h"

namespace sm::field {

class MathExpr {
 public:
  /// Compiles `text`. Throws FieldError ParseError with the 1-based column.
  /// With allow_fields = false, F<n> references are rejected (Param's FX..).
  static MathExpr compile(std::string_view text, bool allow_fields = true);

  /// Distinct field ids referenced as F<n>, in order of first appearance.
  const std::vector<int>& field_refs() const { return refs_; }

  /// out[i] = expression at pts[i]; fields[k][i] is the value of field
  /// field_refs()[k] at pts[i].
  void eval(std::span<const Vec3> pts, std::span<const std::span<const double>> fields,
            std::span<double> out) const;

  /// Number of instructions (after constant folding), for tests.
  std::size_t size() const { return code_.size(); }

  enum class Op : unsigned char {
    X, Y, Z, Field, Add, Sub, Mul, Div, Mod, Pow, Neg,
    Abs, Acos, Asin, Atan, Cos, Cosh, Exp, Log, Log10, Sin, Sinh, Sqrt, Tan, Tanh, Atanh,
    Floor, Ceil, Round, Trunc, Sign, Step, Deg, Rad, Fac, Min, Max, Sum, Med, Rand,
  };

  struct Instr {
    Op op;
    int dst = 0;
    int a = 0, b = 0;  ///< operand registers; Field: index into fields; variadic: args_[a..a+b)
  };

 private:
  std::vector<Instr> code_;
  std::vector<int> args_;
  std::vector<double> consts_;  ///< value per register, used where is_const_
  std::vector<char> is_const_;
  std::vector<int> refs_;
  int result_ = 0;

  friend class MathParser;
};

}  // namespace sm::field
