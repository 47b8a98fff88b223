// TimeStep field: the smallest mesh size an explicit ocean model can use at a given
// time step, h = Dt sqrt(g H) / Courant (a gravity wave crosses an element in no less
// than Dt / Courant); combined with Max, the mesh runs at that Dt. The depth H comes from
// a depth field or a relief grid, raised to MinDepth.
#include <algorithm>
#include <cmath>

#include "field/bathymetry.h"
#include "field/kinds.h"

namespace sm::field {

namespace {

constexpr double kGravity = 9.81;   // m/s^2, as mesh/time_step.h

class TimeStepSize final : public CompositeField {
 public:
  TimeStepSize(FieldPtr depth, LonLatGrid grid, double radius, double scale, double min_depth)
      : depth_(std::move(depth)), grid_(std::move(grid)), radius_(radius), scale_(scale), min_depth_(min_depth) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    if (depth_) {
      eval_input(*depth_, on, pts, h);
    } else {
      for (std::size_t i = 0; i < pts.size(); ++i) {
        double lon, lat;
        lonlat_of(pts[i], radius_, lon, lat);
        h[i] = grid_.interp(lon, lat);
      }
    }
    for (double& v : h) v = scale_ * std::sqrt(std::max(v, min_depth_));
  }

 private:
  FieldPtr depth_;
  LonLatGrid grid_;
  double radius_, scale_, min_depth_;
};

FieldPtr make_time_step_size(const BuildInputs& in) {
  const Options& o = in.opts;
  const double dt = o.number("Dt"), courant = o.number("Courant"), min_depth = o.number("MinDepth");
  if (!(dt > 0)) in.bad("Dt", "must be positive (seconds)");
  if (!(courant > 0)) in.bad("Courant", "must be positive");
  if (!(min_depth > 0)) in.bad("MinDepth", "must be positive (metres)");
  const bool by_field = o.number("DepthField") > 0, by_file = !o.string("FileName").empty();
  if (by_field == by_file) in.bad("DepthField", "give either DepthField or FileName");
  FieldPtr depth;
  LonLatGrid grid;
  if (by_field) {
    depth = in.field(static_cast<int>(o.number("DepthField")), "DepthField");
  } else {
    grid = read_depth_grid(in);
  }
  return std::make_shared<TimeStepSize>(std::move(depth), std::move(grid), o.number("Radius"),
                                        dt * std::sqrt(kGravity) / courant, min_depth);
}

// DepthField is a plain number (0: none, FileName instead), referenced only when set.
std::vector<int> depth_ref(const Options& o) {
  const int id = static_cast<int>(o.number("DepthField"));
  return id > 0 ? std::vector<int>{id} : std::vector<int>{};
}

}  // namespace

KindSpec time_step_kind() {
  std::vector<OptionSpec> opts = {
      num_opt("DepthField", 0, "field giving the depth H in metres, positive down (or FileName)"),
      num_opt("Dt", 0, "the time step, seconds (required, positive)"),
      num_opt("Courant", 1, "the Courant number allowed"),
      num_opt("Radius", 0, "with FileName: sphere radius for the latitude of a point (0: |X|)"),
  };
  for (OptionSpec& s : depth_grid_options()) opts.push_back(std::move(s));
  return {"TimeStep",
          "The smallest size allowed for an explicit time step: Dt*sqrt(9.81 H)/Courant, H the depth "
          "(DepthField, or the relief grid of FileName as Bathymetry reads it) raised to MinDepth. "
          "Use it in a Max with the other criteria so that the mesh runs at Dt.",
          std::move(opts), make_time_step_size, depth_ref};
}

}  // namespace sm::field
