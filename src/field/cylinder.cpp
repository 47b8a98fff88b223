// Cylinder field: VIn inside a finite cylinder C +- axis, VOut outside.
#include <cmath>

#include "field/kinds.h"

namespace sm::field {
namespace {

class CylinderField final : public SizeField {
 public:
  CylinderField(Vec3 c, Vec3 axis, double r, double v_in, double v_out)
      : c_(c), axis_(axis), r_(r), v_in_(v_in), v_out_(v_out) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    const double a2 = norm2(axis_);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec3 d = pts[i] - c_;
      // Position along the axis in units of the half-height |axis|.
      const double t = dot(d, axis_) / a2;
      if (std::fabs(t) > 1) {
        h[i] = v_out_;
        continue;
      }
      h[i] = norm2(d - t * axis_) < r_ * r_ ? v_in_ : v_out_;
    }
  }

 private:
  Vec3 c_, axis_;
  double r_, v_in_, v_out_;
};

FieldPtr make_cylinder(const BuildInputs& in) {
  const Options& o = in.opts;
  const Vec3 axis{o.number("XAxis"), o.number("YAxis"), o.number("ZAxis")};
  if (norm2(axis) == 0) in.bad("ZAxis", "the axis vector must not be zero");
  return std::make_shared<CylinderField>(
      Vec3{o.number("XCenter"), o.number("YCenter"), o.number("ZCenter")}, axis,
      o.number("Radius"), o.number("VIn"), o.number("VOut"));
}

}  // namespace

KindSpec cylinder_kind() {
  return {"Cylinder",
          "VIn inside the cylinder of the given Radius around C +- axis (the axis length is the "
          "half-height), VOut outside.",
          {
              num_opt("Radius", 0, "radius"), num_opt("VIn", 0, "value inside"),
              num_opt("VOut", 0, "value outside"), num_opt("XAxis", 0, "x of the axis vector"),
              num_opt("YAxis", 0, "y of the axis vector"), num_opt("ZAxis", 1, "z of the axis vector"),
              num_opt("XCenter", 0, "x of the centre"), num_opt("YCenter", 0, "y of the centre"),
              num_opt("ZCenter", 0, "z of the centre"),
          },
          make_cylinder};
}

}  // namespace sm::field
