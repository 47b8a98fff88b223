// The size graded from the coast's two-point curves (see coastline_short_curves.h).
#include "interp/kernel/coastline_short_curves.h"

#include "field/short_curve_grading.h"

namespace sm::interp {

field::FieldPtr with_short_curve_grading(const KernelState& k, field::FieldPtr background) {
  if (!background) return background;
  const double growth = kShortCurveGrowth;
  std::vector<field::GradingSeed> seeds;
  for (int tag : coastline_two_point_curves(k)) {
    const geo::ModelCurve* mc = k.model.curve(tag);
    if (!mc || !mc->shape || mc->periodic()) continue;
    const geo::ModelVertex* a = k.model.vertex(mc->begin);
    const geo::ModelVertex* b = k.model.vertex(mc->end);
    if (!a || !b) continue;
    const double length = norm(b->xyz - a->xyz);
    const Vec3 mid = mc->shape->eval(0.5).p;
    double h = 0;
    background->eval_on(field::EntityRef{1, tag}, std::span<const Vec3>(&mid, 1), std::span<double>(&h, 1));
    if (!(length > 0) || !(length < h)) continue;   // one edge of its own size: nothing to grade
    seeds.push_back({a->xyz, length});
    seeds.push_back({b->xyz, length});
  }
  if (seeds.empty()) return background;
  return field::short_curve_grading(std::move(background), std::move(seeds), growth);
}

}  // namespace sm::interp
