// The size graded away from short boundary curves (see short_curve_grading.h).
#include "field/short_curve_grading.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sm::field {

namespace {

class ShortCurveGrading final : public CompositeField {
 public:
  ShortCurveGrading(FieldPtr size, std::vector<GradingSeed> seeds, double growth)
      : size_(std::move(size)), seeds_(std::move(seeds)), growth_(growth) {
    // Sorted by x, so that a point looks only at the seeds whose x lies within the
    // distance where they could lower its size: (size - shortest length) / growth.
    std::sort(seeds_.begin(), seeds_.end(), [](const GradingSeed& a, const GradingSeed& b) {
      return a.at.x < b.at.x || (a.at.x == b.at.x && (a.at.y < b.at.y || (a.at.y == b.at.y && a.at.z < b.at.z)));
    });
    shortest_ = seeds_.empty() ? 0.0 : seeds_.front().length;
    for (const GradingSeed& s : seeds_) shortest_ = std::min(shortest_, s.length);
  }

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    eval_input(*size_, on, pts, h);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec3 p = pts[i];
      if (!(h[i] > shortest_)) continue;
      const double reach = (h[i] - shortest_) / growth_;
      auto it = std::lower_bound(seeds_.begin(), seeds_.end(), p.x - reach,
                                 [](const GradingSeed& s, double x) { return s.at.x < x; });
      for (; it != seeds_.end() && it->at.x <= p.x + reach; ++it)
        h[i] = std::min(h[i], it->length + growth_ * norm(p - it->at));
    }
  }

 private:
  FieldPtr size_;
  std::vector<GradingSeed> seeds_;
  double growth_;
  double shortest_ = 0;
};

}  // namespace

FieldPtr short_curve_grading(FieldPtr size, std::vector<GradingSeed> seeds, double growth) {
  return std::make_shared<ShortCurveGrading>(std::move(size), std::move(seeds), growth);
}

}  // namespace sm::field
