// Finite-difference stencils shared by Gradient, Laplacian, Mean, Curvature
// and MaxEigenHessian: the input is evaluated at x + offset_k for all points
// of a chunk in one batch, then `combine` reduces the k values of each point.
#pragma once

#include <algorithm>
#include <vector>

#include "field/registry.h"

namespace sm::field {

template <class Combine>
class StencilField final : public CompositeField {
 public:
  StencilField(FieldPtr in, std::vector<Vec3> offsets, Combine combine)
      : in_(std::move(in)), offsets_(std::move(offsets)), combine_(std::move(combine)) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    constexpr std::size_t kChunk = 2048;
    const std::size_t k = offsets_.size();
    std::vector<Vec3> q(std::min(pts.size(), kChunk) * k);
    std::vector<double> v(q.size());
    for (std::size_t b = 0; b < pts.size(); b += kChunk) {
      const std::size_t n = std::min(kChunk, pts.size() - b);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < k; ++j) q[i * k + j] = pts[b + i] + offsets_[j];
      eval_input(*in_, on, std::span<const Vec3>(q.data(), n * k), std::span<double>(v.data(), n * k));
      for (std::size_t i = 0; i < n; ++i) h[b + i] = combine_(&v[i * k]);
    }
  }

 private:
  FieldPtr in_;
  std::vector<Vec3> offsets_;
  Combine combine_;
};

template <class Combine>
FieldPtr make_stencil(FieldPtr in, std::vector<Vec3> offsets, Combine combine) {
  return std::make_shared<StencilField<Combine>>(std::move(in), std::move(offsets), std::move(combine));
}

/// The step of a finite-difference field: Delta, or bbox_diag/1e4 when 0
/// (Gmsh >= 4.9's default; 4.8.4's 0 would divide by zero).
inline double stencil_delta(const BuildInputs& in) {
  const double d = in.opts.number("Delta");
  if (d < 0 || !std::isfinite(d)) in.bad("Delta", "must be a positive step (0: bbox diagonal/1e4)");
  return d > 0 ? d : in.ctx.bbox_diag / 1e4;
}

/// Unit axis vector a (0 = x, 1 = y, 2 = z) scaled by s.
inline Vec3 axis(int a, double s) {
  return a == 0 ? Vec3{s, 0, 0} : a == 1 ? Vec3{0, s, 0} : Vec3{0, 0, s};
}

}  // namespace sm::field
