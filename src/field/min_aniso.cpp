// MinAniso (Gmsh 4.8.4's "intersection of a list of possibly anisotropic fields"). Every
// field of this module is a scalar (isotropic) size, so the intersection of the metrics
// 1/h_i^2 I is (1 / min h_i)^2 I and the field is the minimum of its inputs, with Gmsh's
// cap: its scalar evaluation starts the intersection from the metric 1/MAX_LC I (not
// 1/MAX_LC^2), so no size exceeds sqrt(MAX_LC) = 1e11, an empty list included
// (docs/fields.md, "MinAniso").
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "field/field.h"
#include "field/kinds.h"

namespace sm::field {
namespace {

class MinAnisoField final : public CompositeField {
 public:
  explicit MinAnisoField(std::vector<std::pair<int, FieldPtr>> in) : in_(std::move(in)) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    std::fill(h.begin(), h.end(), std::sqrt(kMaxLc));
    std::vector<double> tmp(pts.size());
    for (const auto& [id, f] : in_) {
      eval_input(*f, on, pts, tmp);
      for (std::size_t i = 0; i < pts.size(); ++i) h[i] = std::min(h[i], tmp[i]);
    }
  }

 private:
  std::vector<std::pair<int, FieldPtr>> in_;
};

FieldPtr make_min_aniso(const BuildInputs& in) { return std::make_shared<MinAnisoField>(in.inputs("FieldsList")); }

}  // namespace

KindSpec min_aniso_kind() {
  return {"MinAniso",
          "Intersection of the listed fields' metrics (Gmsh 4.8.4's MinAniso). Every field here is "
          "isotropic, so it is their minimum, never above 1e11 (Gmsh's start metric 1/1e22: an "
          "empty list gives 1e11).",
          {list_opt("FieldsList", "ids of the fields to intersect", {}, OptionRole::FieldRefList)},
          make_min_aniso};
}

}  // namespace sm::field
