// Restrict field: Field[InField] on the listed entities, 1e22 elsewhere
// (Gmsh 4.8.4 semantics: the lists are exact, boundaries are not added).
#include <algorithm>

#include "field/entity_lists.h"
#include "field/kinds.h"

namespace sm::field {
namespace {

class RestrictField final : public SizeField {
 public:
  RestrictField(FieldPtr in, EntityLists lists) : in_(std::move(in)), lists_(std::move(lists)) {}

  /// Without an entity context the restriction cannot apply: InField.
  void eval(std::span<const Vec3> pts, std::span<double> h) const override { in_->eval(pts, h); }

  void eval_on(const EntityRef& on, std::span<const Vec3> pts, std::span<double> h) const override {
    if (lists_.contains(on)) {
      in_->eval_on(on, pts, h);
    } else {
      std::fill(h.begin(), h.end(), kMaxLc);
    }
  }

 private:
  FieldPtr in_;
  EntityLists lists_;
};

FieldPtr make_restrict(const BuildInputs& in) {
  return std::make_shared<RestrictField>(in.input("InField"), EntityLists(in.opts));
}

}  // namespace

KindSpec restrict_kind() {
  return {"Restrict",
          "Field[InField] on the listed entities and 1e22 elsewhere; InField when evaluated "
          "without an entity.",
          {
              field_opt("InField", 1, "field to restrict", {"IField"}),
              list_opt("PointsList", "point tags", {"VerticesList"}),
              list_opt("CurvesList", "curve tags", {"EdgesList"}),
              list_opt("SurfacesList", "surface tags", {"FacesList"}),
              list_opt("VolumesList", "volume tags", {"RegionsList"}),
          },
          make_restrict};
}

}  // namespace sm::field
