// Param field: Field[InField] at (FX(x,y,z), FY(x,y,z), FZ(x,y,z)), a change of
// coordinates given as three MathEx expressions.
#include <array>
#include <vector>

#include "field/error.h"
#include "field/kinds.h"
#include "field/math_expr.h"

namespace sm::field {
namespace {

class ParamField final : public CompositeField {
 public:
  ParamField(FieldPtr in, std::array<MathExpr, 3> f) : in_(std::move(in)), f_(std::move(f)) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    std::vector<double> c(3 * pts.size());
    for (std::size_t k = 0; k < 3; ++k)
      f_[k].eval(pts, {}, std::span<double>(c.data() + k * pts.size(), pts.size()));
    std::vector<Vec3> q(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
      q[i] = {c[i], c[pts.size() + i], c[2 * pts.size() + i]};
    eval_input(*in_, on, q, h);
  }

 private:
  FieldPtr in_;
  std::array<MathExpr, 3> f_;
};

FieldPtr make_param(const BuildInputs& in) {
  // An empty expression keeps the coordinate (Gmsh would fail to parse it).
  auto expr = [&](const char* opt, const char* ident) {
    const std::string& s = in.opts.string(opt);
    try {
      return MathExpr::compile(s.empty() ? ident : s, /*allow_fields=*/false);
    } catch (FieldError& e) {
      e.option = opt;
      throw;
    }
  };
  return std::make_shared<ParamField>(in.input("InField"),
                                      std::array<MathExpr, 3>{expr("FX", "x"), expr("FY", "y"),
                                                              expr("FZ", "z")});
}

}  // namespace

KindSpec param_kind() {
  return {"Param",
          "Field[InField] evaluated at (FX, FY, FZ), three MathEx expressions in x, y, z.",
          {
              field_opt("InField", 1, "field evaluated at the mapped point", {"IField"}),
              str_opt("FX", "", "new x as an expression in x, y, z (empty: x)"),
              str_opt("FY", "", "new y as an expression in x, y, z (empty: y)"),
              str_opt("FZ", "", "new z as an expression in x, y, z (empty: z)"),
          },
          make_param};
}

}  // namespace sm::field
