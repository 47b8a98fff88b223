// Triangle quality in space (see element_quality.h).
#include "io/element_quality.h"

namespace sm::io {

double triangle_rho(Vec3 a, Vec3 b, Vec3 c) {
  const double la = norm(b - c), lb = norm(c - a), lc = norm(a - b);
  const double area2 = norm2(cross(b - a, c - a)) / 4;  // A^2
  const double den = (la + lb + lc) * la * lb * lc;
  return den > 0 ? 16 * area2 / den : 0;
}

}  // namespace sm::io
