// The rare tie-breaking path of the id-perturbed in-circle test.
#include "mesh/geometry.h"

#include <utility>

namespace sm {

Sign incircle_sos_tie(Vec2 a, Vec2 b, Vec2 c, Vec2 d, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                      std::uint32_t id, PredicateStats* st) {
  // det of rows (x, y, x^2 + y^2 + eps_i, 1) is linear in the lifts: the
  // coefficient of eps_a is +orient(b,c,d), of eps_b -orient(a,c,d), of eps_c
  // +orient(a,b,d), of eps_d -orient(a,b,c). The largest id has the dominant
  // eps; the first non-zero coefficient in decreasing id order gives the sign.
  // (Lifting d pushes it outside: its coefficient is -orient(a,b,c) < 0.)
  const std::uint32_t ids[4] = {ia, ib, ic, id};
  int order[4] = {0, 1, 2, 3};
  for (int i = 1; i < 4; ++i)
    for (int j = i; j > 0 && ids[order[j]] > ids[order[j - 1]]; --j) std::swap(order[j], order[j - 1]);
  for (int k : order) {
    Sign s;
    switch (k) {
      case 0: s = orient2d(b, c, d, st); break;
      case 1: s = -orient2d(a, c, d, st); break;
      case 2: s = orient2d(a, b, d, st); break;
      default: s = -orient2d(a, b, c, st); break;
    }
    if (s != Sign::Zero) return s;
  }
  return Sign::Zero;
}

}  // namespace sm
