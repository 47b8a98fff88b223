// Mesh statistics in the plane: rho, gamma (exact/quality.h: every quality measure) and
// edge length over the target size (median and 5-95% range); circumcircles.
#pragma once

#include <cstdint>
#include <functional>

#include "base/vec.h"
#include "exact/quality.h"
#include "mesh/triangulation.h"

namespace sm {

/// Circumcentre and circumradius (inexact constructions).
Vec2 circumcentre(Vec2 a, Vec2 b, Vec2 c);
double circumradius(Vec2 a, Vec2 b, Vec2 c);

struct QualityStats {
  std::uint32_t nodes = 0, triangles = 0, edges = 0;
  double min_rho = 0, mean_rho = 0, share_rho_09 = 0;  // share of triangles with rho > 0.9
  double min_gamma = 0, mean_gamma = 0;
  double len_median = 0, len_p05 = 0, len_p95 = 0;     // edge length / target size
  double share_len_07_14 = 0;                          // share of edges with ratio in [0.7, 1.4]
};

/// Statistics over the live triangles of m; `size` gives the target size at
/// an edge midpoint (nullptr: ratios are plain lengths).
QualityStats mesh_quality(const TriangleStore& m, const std::function<double(Vec2)>& size = nullptr);

}  // namespace sm
