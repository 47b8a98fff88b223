// The valence change of a flip (flip_valence.h).
#include "mesh/modify/flip_valence.h"

namespace sm {

int free_valence(const TriangleStore& m, VertexId v, std::uint32_t fixed_count) {
  if (v.value < fixed_count || !m.out_side_ok(v)) return -1;
  int n = 0;
  const FanEnd end = for_each_fan_side(m, m.out_side[v.value], [&](Side x) {
    if (m.constrained(x)) return false;
    ++n;
    return true;
  });
  return end == FanEnd::Closed ? n : -1;
}

int flip_valence_rise(const TriangleStore& m, Side s, std::uint32_t fixed_count) {
  const Side o = m.twin[s.value];
  const VertexId corners[4] = {m.org(s), m.dest(s), m.apex(s), m.apex(o)};
  int rise = 0;
  for (int i = 0; i < 4; ++i) {
    const int k = free_valence(m, corners[i], fixed_count);
    if (k < 0) continue;
    // (k - 1 - 6)^2 - (k - 6)^2 for the ends, (k + 1 - 6)^2 - (k - 6)^2 for the apexes.
    rise += i < 2 ? 13 - 2 * k : 2 * k - 11;
  }
  return rise;
}

}  // namespace sm
