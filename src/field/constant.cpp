// Constant field (Gmsh >= 4.9): VIn on the listed entities, VOut elsewhere.
#include <algorithm>

#include "field/entity_lists.h"
#include "field/kinds.h"

namespace sm::field {
namespace {

class ConstantField final : public SizeField {
 public:
  ConstantField(double v_in, double v_out, EntityLists lists)
      : v_in_(v_in), v_out_(v_out), lists_(std::move(lists)) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    std::fill(h.begin(), h.end(), v_out_);
  }

  void eval_on(const EntityRef& on, std::span<const Vec3> pts, std::span<double> h) const override {
    std::fill(h.begin(), h.end(), lists_.contains(on) ? v_in_ : v_out_);
  }

 private:
  double v_in_, v_out_;
  EntityLists lists_;
};

FieldPtr make_constant(const BuildInputs& in) {
  return std::make_shared<ConstantField>(in.opts.number("VIn"), in.opts.number("VOut"),
                                         EntityLists(in.opts));
}

}  // namespace

KindSpec constant_kind() {
  return {"Constant",
          "VIn on the listed entities, VOut elsewhere and when evaluated without an entity.",
          {
              num_opt("VIn", kMaxLc, "value on the listed entities"),
              num_opt("VOut", kMaxLc, "value elsewhere"),
              list_opt("PointsList", "point tags", {"VerticesList"}),
              list_opt("CurvesList", "curve tags", {"EdgesList"}),
              list_opt("SurfacesList", "surface tags", {"FacesList"}),
              list_opt("VolumesList", "volume tags", {"RegionsList"}),
          },
          make_constant};
}

}  // namespace sm::field
