// MaxEigenHessian field: largest eigenvalue of the finite-difference Hessian
// of Field[InField].
#include <algorithm>
#include <cmath>
#include <numbers>

#include "field/kinds.h"
#include "field/stencil.h"

namespace sm::field {
namespace {

/// Largest eigenvalue of the symmetric matrix [a d e; d b f; e f c]
/// (closed form of the characteristic cubic, trigonometric branch).
double max_eigenvalue(double a, double b, double c, double d, double e, double f) {
  const double p1 = d * d + e * e + f * f;
  if (p1 == 0) return std::max({a, b, c});
  const double q = (a + b + c) / 3;
  const double p2 = (a - q) * (a - q) + (b - q) * (b - q) + (c - q) * (c - q) + 2 * p1;
  const double p = std::sqrt(p2 / 6);
  const double ba = (a - q) / p, bb = (b - q) / p, bc = (c - q) / p, bd = d / p, be = e / p,
               bf = f / p;
  const double det = ba * (bb * bc - bf * bf) - bd * (bd * bc - bf * be) + be * (bd * bf - bb * be);
  const double r = std::clamp(det / 2, -1.0, 1.0);
  return q + 2 * p * std::cos(std::acos(r) / 3);
}

FieldPtr make_max_eigen_hessian(const BuildInputs& in) {
  const double d = stencil_delta(in);
  // 0: centre; 1..6: +-d along x, y, z; then for (x,y), (x,z), (y,z) the
  // four diagonal points (+,+), (-,-), (-,+), (+,-) at half steps.
  std::vector<Vec3> off = {Vec3{}};
  for (int a = 0; a < 3; ++a) {
    off.push_back(axis(a, d));
    off.push_back(axis(a, -d));
  }
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (const auto& p : pairs) {
    const double h = d / 2;
    off.push_back(axis(p[0], h) + axis(p[1], h));
    off.push_back(axis(p[0], -h) + axis(p[1], -h));
    off.push_back(axis(p[0], -h) + axis(p[1], h));
    off.push_back(axis(p[0], h) + axis(p[1], -h));
  }
  return make_stencil(in.input("InField"), std::move(off), [d](const double* v) {
    const double d2 = d * d;
    const double xx = (v[1] + v[2] - 2 * v[0]) / d2, yy = (v[3] + v[4] - 2 * v[0]) / d2,
                 zz = (v[5] + v[6] - 2 * v[0]) / d2;
    const double xy = (v[7] + v[8] - v[9] - v[10]) / d2, xz = (v[11] + v[12] - v[13] - v[14]) / d2,
                 yz = (v[15] + v[16] - v[17] - v[18]) / d2;
    return max_eigenvalue(xx, yy, zz, xy, xz, yz);
  });
}

}  // namespace

KindSpec max_eigen_hessian_kind() {
  return {"MaxEigenHessian",
          "Largest eigenvalue of the finite-difference Hessian of Field[InField].",
          {
              field_opt("InField", 1, "field whose Hessian is computed", {"IField"}),
              num_opt("Delta", 0, "finite-difference step (0: bbox diagonal / 1e4)"),
          },
          make_max_eigen_hessian};
}

}  // namespace sm::field
