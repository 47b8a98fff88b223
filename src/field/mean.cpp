// Mean field: average of Field[InField] at x and its six neighbours x +- d e_k.
#include "field/kinds.h"
#include "field/stencil.h"

namespace sm::field {
namespace {

FieldPtr make_mean(const BuildInputs& in) {
  const double d = stencil_delta(in);
  std::vector<Vec3> off = {Vec3{}};
  for (int a = 0; a < 3; ++a) {
    off.push_back(axis(a, d));
    off.push_back(axis(a, -d));
  }
  return make_stencil(in.input("InField"), std::move(off), [](const double* v) {
    return (v[0] + v[1] + v[2] + v[3] + v[4] + v[5] + v[6]) / 7;
  });
}

}  // namespace

KindSpec mean_kind() {
  return {"Mean", "Average of Field[InField] at x and at the six points x +- Delta e_k.",
          {
              field_opt("InField", 1, "field to smooth", {"IField"}),
              num_opt("Delta", 0, "distance of the neighbours (0: bbox diagonal / 1e4)"),
          },
          make_mean};
}

}  // namespace sm::field
