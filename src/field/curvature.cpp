// Curvature field: divergence of the normalised finite-difference gradient of
// Field[InField], i.e. the mean curvature of its level sets (times 2).
#include <cmath>

#include "field/kinds.h"
#include "field/stencil.h"

namespace sm::field {
namespace {

FieldPtr make_curvature(const BuildInputs& in) {
  const double d = stencil_delta(in);
  // For each of the six points x +- d/2 e_a, the six points of a central
  // gradient around it: offset index = (2a + side) * 6 + (2b + side').
  std::vector<Vec3> off;
  for (int a = 0; a < 3; ++a)
    for (double s : {0.5, -0.5})
      for (int b = 0; b < 3; ++b)
        for (double t : {0.5, -0.5}) off.push_back(axis(a, s * d) + axis(b, t * d));
  return make_stencil(in.input("InField"), std::move(off), [d](const double* v) {
    double div = 0;
    for (int a = 0; a < 3; ++a) {
      double comp[2];
      for (int side = 0; side < 2; ++side) {
        const double* g = v + (2 * a + side) * 6;
        const double gx = (g[0] - g[1]) / d, gy = (g[2] - g[3]) / d, gz = (g[4] - g[5]) / d;
        const double n = std::sqrt(gx * gx + gy * gy + gz * gz);
        const double c = a == 0 ? gx : a == 1 ? gy : gz;
        comp[side] = n > 0 ? c / n : 0.0;
      }
      div += comp[0] - comp[1];
    }
    return div / d;
  });
}

}  // namespace

KindSpec curvature_kind() {
  return {"Curvature",
          "Divergence of the normalised gradient of Field[InField] (finite differences of step "
          "Delta).",
          {
              field_opt("InField", 1, "field whose level-set curvature is computed", {"IField"}),
              num_opt("Delta", 0, "finite-difference step (0: bbox diagonal / 1e4)"),
          },
          make_curvature};
}

}  // namespace sm::field
