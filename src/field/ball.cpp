// Ball field: VIn inside a ball, VOut outside, optional ramp.
#include <cmath>

#include "field/kinds.h"
#include "field/shapes.h"

namespace sm::field {
namespace {

class BallField final : public SizeField {
 public:
  BallField(Vec3 c, double r, double thick, double v_in, double v_out)
      : c_(c), r_(r), thick_(thick), v_in_(v_in), v_out_(v_out) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double d = norm(pts[i] - c_);
      h[i] = d < r_ ? v_in_ : ramp_out(d - r_, thick_, v_in_, v_out_);
    }
  }

 private:
  Vec3 c_;
  double r_, thick_, v_in_, v_out_;
};

FieldPtr make_ball(const BuildInputs& in) {
  const Options& o = in.opts;
  if (o.number("Radius") < 0) in.bad("Radius", "must not be negative");
  return std::make_shared<BallField>(
      Vec3{o.number("XCenter"), o.number("YCenter"), o.number("ZCenter")}, o.number("Radius"),
      o.number("Thickness"), o.number("VIn"), o.number("VOut"));
}

}  // namespace

KindSpec ball_kind() {
  return {"Ball",
          "VIn where |X - C| < Radius, VOut outside, with a linear ramp over Thickness.",
          {
              num_opt("Radius", 0, "radius of the ball"),
              num_opt("Thickness", 0, "width of the VIn-to-VOut transition outside the ball"),
              num_opt("VIn", 0, "value inside the ball"),
              num_opt("VOut", 0, "value outside the ball"),
              num_opt("XCenter", 0, "x of the centre"), num_opt("YCenter", 0, "y of the centre"),
              num_opt("ZCenter", 0, "z of the centre"),
          },
          make_ball};
}

}  // namespace sm::field
