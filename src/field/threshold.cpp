// Threshold: the paper's clamp delta_small + alpha(f)(delta_large - delta_small)
// of section 3.1 (linear or sigmoid ramp), Gmsh's Threshold field.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "field/batch_pieces.h"
#include "field/bounded_field.h"
#include "field/kinds.h"

namespace sm::field {
namespace {

class ThresholdField final : public CompositeField, public MinInput {
 public:
  ThresholdField(FieldPtr in, double size_min, double size_max, double dist_min, double dist_max,
                 bool sigmoid, bool stop)
      : in_(std::move(in)), size_min_(size_min), size_max_(size_max), dist_min_(dist_min),
        dist_max_(dist_max), sigmoid_(sigmoid), stop_(stop), bounded_(dynamic_cast<const BoundedEval*>(in_.get())) {}

  // Inside a Min: only a distance below the one whose size is h[i] can lower h[i], so a
  // Distance input is searched that far (and no farther than DistMax, beyond which
  // every distance gives the same size). The ramp is inverted with a margin of
  // kRampMargin in r: beyond the limit the computed size is at least h[i] whatever the
  // rounding (the sizes' spread, at least kSpread of SizeMax, keeps the margin's size
  // step far above it), so the result is that of evaluating and taking the min.
  void lower(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    // In pieces whose scratch lives on the stack (field/batch_pieces.h).
    for_each_piece(pts.size(), [&](std::size_t from, std::size_t n) {
      lower_piece(on, pts.subspan(from, n), h.subspan(from, n));
    });
  }

  // Where the margin would not cover the rounding (a sigmoid, sizes almost equal,
  // DistMin far from 0 against the span), or the input cannot stop early, lower()
  // evaluates every point.
  bool prunes() const override {
    constexpr double kSpread = 1e-5, kFarOrigin = 1e3;
    const double span = dist_max_ - dist_min_;
    const double spread = size_max_ - size_min_;
    const bool invertible = !sigmoid_ && std::isfinite(span) && span > 0 && spread > kSpread * size_max_ &&
                            std::fabs(dist_min_) <= kFarOrigin * span;
    return bounded_ && invertible;
  }

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    // Every input above DistMax gives r = 1 (and StopAtDistMax's MAX_LC), so those
    // values need not be exact: a Distance input stops its search there.
    if (bounded_ && std::isfinite(dist_max_ - dist_min_)) {
      bounded_->eval_below(pts, std::span<const double>(&dist_max_, 1), h);
    } else {
      eval_input(*in_, on, pts, h);
    }
    for (double& v : h) v = size_at(v);
  }

 private:
  void lower_piece(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const {
    constexpr double kRampMargin = 1e-9, kBelowMin = 1e-12;
    const double span = dist_max_ - dist_min_;
    const double spread = size_max_ - size_min_;
    double v[kBatchPiece];  // not initialised: written before read
    if (!prunes()) {
      run(on, pts, std::span<double>(v, pts.size()));
      for (std::size_t i = 0; i < h.size(); ++i)
        if (v[i] < h[i]) h[i] = v[i];
      return;
    }
    std::uint32_t which[kBatchPiece];
    PiecePoints at;  // not initialised either: the first `count` are assigned below
    double limit[kBatchPiece];
    std::size_t count = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
      // No distance gives a size below SizeMin (up to rounding).
      if (h[i] < size_min_ * (1 - kBelowMin)) continue;
      double lim = dist_max_;  // also for a NaN h
      if (h[i] < size_max_) lim = std::min(lim, dist_min_ + ((h[i] - size_min_) / spread + kRampMargin) * span);
      which[count] = static_cast<std::uint32_t>(i);
      at.p[count] = pts[i];
      limit[count] = lim;
      ++count;
    }
    if (count == 0) return;
    bounded_->eval_below(std::span<const Vec3>(at.p, count), std::span<const double>(limit, count),
                         std::span<double>(v, count));
    for (std::size_t k = 0; k < count; ++k) {
      const double x = size_at(v[k]);
      if (x < h[which[k]]) h[which[k]] = x;
    }
  }

  double size_at(double d) const {
    const double span = dist_max_ - dist_min_;
    // DistMin == DistMax is a step at DistMin (Gmsh would divide by zero).
    double r = span > 0 ? (d - dist_min_) / span : (d > dist_min_ ? 1.0 : 0.0);
    r = std::clamp(r, 0.0, 1.0);
    if (sigmoid_) {
      const double e = std::exp(12 * r - 6);
      r = e / (1 + e);
    }
    const double v = size_min_ * (1 - r) + size_max_ * r;
    return stop_ && d >= dist_max_ ? kMaxLc : v;
  }

  FieldPtr in_;
  double size_min_, size_max_, dist_min_, dist_max_;
  bool sigmoid_, stop_;
  const BoundedEval* bounded_;  // in_ itself, when it can stop early
};

FieldPtr make_threshold(const BuildInputs& in) {
  const Options& o = in.opts;
  const double smin = o.number("SizeMin"), smax = o.number("SizeMax");
  const double dmin = o.number("DistMin"), dmax = o.number("DistMax");
  if (!(smin > 0) || !std::isfinite(smin)) in.bad("SizeMin", "a size must be positive and finite");
  if (!(smax > 0) || !std::isfinite(smax)) in.bad("SizeMax", "a size must be positive and finite");
  if (!std::isfinite(dmin) || !std::isfinite(dmax)) in.bad("DistMin", "distances must be finite");
  if (dmax < dmin) in.bad("DistMax", "DistMax must not be smaller than DistMin");
  return std::make_shared<ThresholdField>(in.input("InField"), smin, smax, dmin, dmax,
                                          o.number("Sigmoid") != 0, o.number("StopAtDistMax") != 0);
}

}  // namespace

KindSpec threshold_kind() {
  return {"Threshold",
          "F = SizeMin if Field[InField] <= DistMin, SizeMax if >= DistMax, a linear (or sigmoid) "
          "ramp between: the paper's delta_small + alpha(f)(delta_large - delta_small).",
          {
              field_opt("InField", 0, "field whose value is the distance (or any criterion f)",
                        {"IField"}),
              num_opt("SizeMin", 0.1, "size where the input is at most DistMin", {"LcMin"}),
              num_opt("SizeMax", 1, "size where the input is at least DistMax", {"LcMax"}),
              num_opt("DistMin", 1, "input value up to which SizeMin applies"),
              num_opt("DistMax", 10, "input value from which SizeMax applies"),
              num_opt("Sigmoid", 0, "1: sigmoid ramp e^(12r-6)/(1+e^(12r-6)) instead of linear"),
              num_opt("StopAtDistMax", 0, "1: return 1e22 (no constraint) where input >= DistMax"),
          },
          make_threshold};
}

}  // namespace sm::field
