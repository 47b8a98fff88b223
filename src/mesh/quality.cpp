// Circumcircles and mesh statistics (the quality measures: exact/quality.h).
#include "mesh/quality.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sm {

Vec2 circumcentre(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 ba = b - a, ca = c - a;
  const double d = 2 * cross(ba, ca);
  const double bl = norm2(ba), cl = norm2(ca);
  return {a.x + (ca.y * bl - ba.y * cl) / d, a.y + (ba.x * cl - ca.x * bl) / d};
}

double circumradius(Vec2 a, Vec2 b, Vec2 c) { return norm(circumcentre(a, b, c) - a); }

QualityStats mesh_quality(const TriangleStore& m, const std::function<double(Vec2)>& size) {
  QualityStats q;
  std::vector<double> ratio;
  std::vector<std::uint8_t> used(m.num_vertices(), 0);
  double sum_rho = 0, sum_gamma = 0;
  q.min_rho = 1, q.min_gamma = 1;
  std::uint32_t good = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
    const double r = rho(a, b, c), gm = gamma(a, b, c);
    ++q.triangles;
    sum_gamma += gm;
    q.min_gamma = std::min(q.min_gamma, gm);
    sum_rho += r;
    q.min_rho = std::min(q.min_rho, r);
    good += r > 0.9;
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      used[m.org(s).value] = 1;
      const Side o = m.twin[s.value];
      if (o.valid() && o.value < s.value) continue;  // each edge once
      const Vec2 p = m.pos(m.org(s)), r2 = m.pos(m.dest(s));
      const double h = size ? size(0.5 * (p + r2)) : 1.0;
      ratio.push_back(norm(r2 - p) / h);
    }
  }
  for (std::uint8_t u : used) q.nodes += u;
  q.edges = static_cast<std::uint32_t>(ratio.size());
  if (q.triangles == 0) return QualityStats{};
  q.mean_rho = sum_rho / q.triangles;
  q.mean_gamma = sum_gamma / q.triangles;
  q.share_rho_09 = double(good) / q.triangles;
  std::sort(ratio.begin(), ratio.end());
  auto pct = [&](double f) {
    return ratio[std::min(ratio.size() - 1, static_cast<std::size_t>(f * static_cast<double>(ratio.size())))];
  };
  q.len_median = pct(0.5), q.len_p05 = pct(0.05), q.len_p95 = pct(0.95);
  std::size_t in = 0;
  for (double r : ratio) in += r >= 0.7 && r <= 1.4;
  q.share_len_07_14 = double(in) / static_cast<double>(ratio.size());
  return q;
}

}  // namespace sm
