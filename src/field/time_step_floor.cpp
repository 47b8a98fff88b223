// Mesh.MinTimeStep's size floor (see time_step_floor.h).
#include "field/time_step_floor.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sm::field {

namespace {

constexpr double kFloorGravity = 9.81;   // m/s^2, as mesh/time_step.h

class TimeStepFloor final : public CompositeField {
 public:
  TimeStepFloor(FieldPtr size, FieldPtr depth, double scale, double min_depth)
      : size_(std::move(size)), depth_(std::move(depth)), scale_(scale), min_depth_(min_depth) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    eval_input(*size_, on, pts, h);
    // Per call, not a member: eval is called from many threads at once (field.h).
    std::vector<double> depth(pts.size());
    eval_input(*depth_, on, pts, depth);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double H = std::max(depth[i], min_depth_);
      if (H > 0) h[i] = std::max(h[i], scale_ * std::sqrt(H));
    }
  }

 private:
  FieldPtr size_, depth_;
  double scale_, min_depth_;
};

}  // namespace

FieldPtr time_step_floor(FieldPtr size, FieldPtr depth, double dt, double min_depth, double factor) {
  return std::make_shared<TimeStepFloor>(std::move(size), std::move(depth), factor * dt * std::sqrt(kFloorGravity),
                                         min_depth);
}

}  // namespace sm::field
