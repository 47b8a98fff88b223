// Test/bench helper: planar domains (square, square with circular holes)
// with boundaries discretised at a uniform size, triangulated and recovered.
#pragma once

#include <cmath>
#include <vector>

#include "mesh/cdt.h"
#include "mesh/delaunay.h"

namespace sm::testing {

/// Points of a closed polyline through `corners`, each side cut into pieces
/// of length <= h; appended to m, returned as a loop.
inline Loop polygon_loop(TriangleStore& m, const std::vector<Vec2>& corners, double h, bool hole) {
  Loop l;
  l.hole = hole;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const int n = std::max(1, static_cast<int>(std::ceil(norm(b - a) / h - 1e-9)));
    for (int k = 0; k < n; ++k) l.v.push_back(m.add_vertex(a + (double(k) / n) * (b - a)));
  }
  return l;
}

inline Loop circle_loop(TriangleStore& m, Vec2 c, double r, double h, bool hole) {
  Loop l;
  l.hole = hole;
  const int n = std::max(3, static_cast<int>(std::ceil(2 * M_PI * r / h)));
  for (int k = 0; k < n; ++k)
    l.v.push_back(m.add_vertex({c.x + r * std::cos(2 * M_PI * k / n), c.y + r * std::sin(2 * M_PI * k / n)}));
  return l;
}

/// Delaunay of the loop points, loop edges recovered, outside removed.
/// Returns false on any failure.
inline bool boundary_mesh(TriangleStore& m, const std::vector<Loop>& loops, std::vector<Edge>* edges_out = nullptr) {
  if (!delaunay(m).ok()) return false;
  std::vector<Edge> edges;
  for (const Loop& l : loops)
    for (std::size_t k = 0; k < l.v.size(); ++k) edges.push_back({l.v[k], l.v[(k + 1) % l.v.size()]});
  const PlanarGeometry g{&m.xy};
  if (!recover_edges(m, g, edges).clean()) return false;
  if (!remove_outside(m, g, loops).ok()) return false;
  if (edges_out) *edges_out = edges;
  return true;
}

}  // namespace sm::testing
