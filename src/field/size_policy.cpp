// Final size combination of Gmsh 4.8.4 (docs/fields.md), as a pure
// function of the options and of what is known at the point.
#include "field/size_policy.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "field/field.h"

namespace sm::field {

bool set_size_option(SizePolicyOptions& o, std::string_view name, double value) {
  if (name.substr(0, 5) == "Mesh.") name.remove_prefix(5);
  std::string_view suffix;
  if (name.substr(0, 8) == "MeshSize") {
    suffix = name.substr(8);
  } else if (name.substr(0, 20) == "CharacteristicLength") {
    suffix = name.substr(20);
  } else {
    return false;
  }
  if (suffix == "Factor") o.factor = value;
  else if (suffix == "Min") o.min = value;
  else if (suffix == "Max") o.max = value;
  else if (suffix == "FromPoints") o.from_points = value != 0;
  else if (suffix == "ExtendFromBoundary") o.extend_from_boundary = static_cast<int>(value);
  else if (suffix == "FromCurvature") o.from_curvature = static_cast<int>(value);
  else return false;
  return true;
}

SizeResult final_size(const SizePolicyOptions& o, const SizeQuery& q) {
  const double bbox = q.bbox_diag > 0 ? q.bbox_diag : 1;
  double lc = bbox;
  if (o.from_points && q.entity_dim == 0) {
    lc = std::min(lc, q.point_lc ? *q.point_lc : bbox / 10);
  } else if (o.from_points && q.entity_dim == 1) {
    if (!q.end_lc0 && !q.end_lc1) {
      lc = std::min(lc, bbox / 10);
    } else {
      // One missing end size interpolates toward MAX_LC (Gmsh's quirk); the
      // bbox cap above keeps the result finite.
      const double a = q.end_lc0.value_or(kMaxLc), b = q.end_lc1.value_or(kMaxLc);
      lc = std::min(lc, a + (b - a) * q.t);
    }
  }
  if (o.from_curvature > 0 && q.curvature && *q.curvature > 0)
    lc = std::min(lc, 2 * std::numbers::pi / (*q.curvature * o.from_curvature));
  if (q.background) lc = std::min(lc, *q.background);
  if (q.entity_size) lc = std::min(lc, *q.entity_size);
  lc = std::max(lc, o.min);
  lc = std::min(lc, o.max);
  SizeResult r;
  if (!(lc > 0)) {
    r.nonpositive = true;
    lc = bbox;
  }
  r.size = lc * q.entity_factor * o.factor;
  return r;
}

namespace {

class MinOnEntities final : public SizeField {
 public:
  MinOnEntities(std::shared_ptr<const SizeField> base, std::shared_ptr<const ChannelWidthField> extra,
                std::set<int> curves, std::set<int> surfaces)
      : base_(std::move(base)), extra_(std::move(extra)), curves_(std::move(curves)), surfaces_(std::move(surfaces)) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override { run(nullptr, pts, h); }
  void eval_on(const EntityRef& on, std::span<const Vec3> pts, std::span<double> h) const override {
    run(&on, pts, h);
  }

 private:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const {
    if (base_) {
      eval_input(*base_, on, pts, h);
    } else {
      std::fill(h.begin(), h.end(), kMaxLc);
    }
    const bool applies = !on || (on->dim == 1 && curves_.count(std::abs(on->tag))) ||
                         (on->dim == 2 && surfaces_.count(std::abs(on->tag)));
    if (!applies) return;
    extra_->lower(pts, h);
  }

  std::shared_ptr<const SizeField> base_;
  std::shared_ptr<const ChannelWidthField> extra_;
  std::set<int> curves_, surfaces_;
};

}  // namespace

std::shared_ptr<const SizeField> min_on_entities(std::shared_ptr<const SizeField> base,
                                                 std::shared_ptr<const ChannelWidthField> extra, std::set<int> curves,
                                                 std::set<int> surfaces) {
  return std::make_shared<MinOnEntities>(std::move(base), std::move(extra), std::move(curves), std::move(surfaces));
}

double surface_target(const SizePolicyOptions& o, double final, std::optional<double> boundary_interp) {
  if (o.extend_from_boundary != 0 && boundary_interp) return std::min(final, *boundary_interp);
  return final;
}

}  // namespace sm::field
