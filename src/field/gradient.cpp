// Gradient field: central difference (f(x+d/2) - f(x-d/2))/d of Field[InField]
// along x, y or z, or the norm of that gradient.
#include <cmath>

#include "field/kinds.h"
#include "field/stencil.h"

namespace sm::field {
namespace {

FieldPtr make_gradient(const BuildInputs& in) {
  const double d = stencil_delta(in);
  const int kind = static_cast<int>(in.opts.number("Kind"));
  if (kind < 0 || kind > 3) in.bad("Kind", "must be 0 (x), 1 (y), 2 (z) or 3 (norm)");
  if (kind < 3)
    return make_stencil(in.input("InField"), {axis(kind, d / 2), axis(kind, -d / 2)},
                        [d](const double* v) { return (v[0] - v[1]) / d; });
  std::vector<Vec3> off;
  for (int a = 0; a < 3; ++a) {
    off.push_back(axis(a, d / 2));
    off.push_back(axis(a, -d / 2));
  }
  return make_stencil(in.input("InField"), std::move(off), [d](const double* v) {
    const double gx = (v[0] - v[1]) / d, gy = (v[2] - v[3]) / d, gz = (v[4] - v[5]) / d;
    return std::sqrt(gx * gx + gy * gy + gz * gz);
  });
}

}  // namespace

KindSpec gradient_kind() {
  return {"Gradient",
          "Central finite difference (f(x+Delta/2) - f(x-Delta/2))/Delta of Field[InField] "
          "along one axis, or the norm of the gradient.",
          {
              field_opt("InField", 1, "field to differentiate", {"IField"}),
              num_opt("Kind", 3, "component: 0 = x, 1 = y, 2 = z, 3 = norm"),
              num_opt("Delta", 0, "finite-difference step (0: bbox diagonal / 1e4)"),
          },
          make_gradient};
}

}  // namespace sm::field
