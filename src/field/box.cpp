// Box field: VIn inside an axis-aligned box, VOut outside, optional ramp.
#include <algorithm>
#include <cmath>

#include "field/kinds.h"
#include "field/shapes.h"

namespace sm::field {
namespace {

class BoxField final : public SizeField {
 public:
  BoxField(Vec3 lo, Vec3 hi, double thick, double v_in, double v_out)
      : lo_(lo), hi_(hi), thick_(thick), v_in_(v_in), v_out_(v_out) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec3 p = pts[i];
      const double dx = std::max({lo_.x - p.x, 0.0, p.x - hi_.x});
      const double dy = std::max({lo_.y - p.y, 0.0, p.y - hi_.y});
      const double dz = std::max({lo_.z - p.z, 0.0, p.z - hi_.z});
      const bool inside = p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y &&
                          p.z >= lo_.z && p.z <= hi_.z;
      h[i] = inside ? v_in_ : ramp_out(std::sqrt(dx * dx + dy * dy + dz * dz), thick_, v_in_, v_out_);
    }
  }

 private:
  Vec3 lo_, hi_;
  double thick_, v_in_, v_out_;
};

FieldPtr make_box(const BuildInputs& in) {
  const Options& o = in.opts;
  return std::make_shared<BoxField>(Vec3{o.number("XMin"), o.number("YMin"), o.number("ZMin")},
                                    Vec3{o.number("XMax"), o.number("YMax"), o.number("ZMax")},
                                    o.number("Thickness"), o.number("VIn"), o.number("VOut"));
}

}  // namespace

KindSpec box_kind() {
  return {"Box",
          "VIn inside the box [XMin,XMax]x[YMin,YMax]x[ZMin,ZMax] (bounds included), VOut "
          "outside, with a linear ramp over Thickness.",
          {
              num_opt("VIn", 0, "value inside the box (Gmsh 4.8.4 default 0)"),
              num_opt("VOut", 0, "value outside the box (Gmsh 4.8.4 default 0)"),
              num_opt("XMin", 0, "lower x bound"), num_opt("XMax", 0, "upper x bound"),
              num_opt("YMin", 0, "lower y bound"), num_opt("YMax", 0, "upper y bound"),
              num_opt("ZMin", 0, "lower z bound"), num_opt("ZMax", 0, "upper z bound"),
              num_opt("Thickness", 0, "width of the VIn-to-VOut transition outside the box"),
          },
          make_box};
}

}  // namespace sm::field
