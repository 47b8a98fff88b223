// MathEval field: a MathEx expression in x, y, z and F<n>, compiled once at
// build time; inputs F<n> are evaluated per batch, never per point.
#include <vector>

#include "field/error.h"
#include "field/kinds.h"
#include "field/math_expr.h"

namespace sm::field {
namespace {

class MathEvalField final : public CompositeField {
 public:
  MathEvalField(MathExpr expr, std::vector<FieldPtr> in) : expr_(std::move(expr)), in_(std::move(in)) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    std::vector<double> vals(in_.size() * pts.size());
    std::vector<std::span<const double>> cols;
    for (std::size_t k = 0; k < in_.size(); ++k) {
      std::span<double> col(vals.data() + k * pts.size(), pts.size());
      eval_input(*in_[k], on, pts, col);
      cols.push_back(col);
    }
    expr_.eval(pts, cols, h);
  }

 private:
  MathExpr expr_;
  std::vector<FieldPtr> in_;
};

MathExpr compile_f(const Options& o) {
  try {
    return MathExpr::compile(o.string("F"));
  } catch (FieldError& e) {
    e.option = "F";   // so the interpreter can point at the statement that set it
    throw;
  }
}

std::vector<int> refs(const Options& o) { return compile_f(o).field_refs(); }

FieldPtr make_math_eval(const BuildInputs& in) {
  MathExpr e = compile_f(in.opts);
  std::vector<FieldPtr> inputs;
  for (int id : e.field_refs()) inputs.push_back(in.field(id, "F"));
  return std::make_shared<MathEvalField>(std::move(e), std::move(inputs));
}

}  // namespace

KindSpec math_eval_kind() {
  return {"MathEval",
          "Value of the MathEx expression F in x, y, z and F<n> (the value of Field[n] at the "
          "same point): operators + - * / % ^, Pi, e, abs acos asin atan cos cosh exp log log10 "
          "sin sinh sqrt tan tanh atanh floor ceil round trunc sign step deg rad fac min max sum "
          "med rand.",
          {str_opt("F", "F2 + Sin(z)", "the expression (MathEx syntax, not the .geo grammar)")},
          make_math_eval, refs};
}

}  // namespace sm::field
