// Laplacian field: (sum over the six neighbours f(x +- d e_k) - 6 f(x)) / d^2.
#include "field/kinds.h"
#include "field/stencil.h"

namespace sm::field {
namespace {

FieldPtr make_laplacian(const BuildInputs& in) {
  const double d = stencil_delta(in);
  std::vector<Vec3> off = {Vec3{}};
  for (int a = 0; a < 3; ++a) {
    off.push_back(axis(a, d));
    off.push_back(axis(a, -d));
  }
  return make_stencil(in.input("InField"), std::move(off), [d](const double* v) {
    return (v[1] + v[2] + v[3] + v[4] + v[5] + v[6] - 6 * v[0]) / (d * d);
  });
}

}  // namespace

KindSpec laplacian_kind() {
  return {"Laplacian",
          "Finite-difference Laplacian (sum of f(x +- Delta e_k) - 6 f(x)) / Delta^2 of "
          "Field[InField].",
          {
              field_opt("InField", 1, "field to differentiate", {"IField"}),
              num_opt("Delta", 0.1, "finite-difference step (Gmsh 4.8.4 default 0.1; 0: bbox/1e4)"),
          },
          make_laplacian};
}

}  // namespace sm::field
