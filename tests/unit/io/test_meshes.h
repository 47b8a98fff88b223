// Small meshes built in code for the writer tests.
#pragma once

#include <cmath>

#include "io/mesh_model.h"

namespace sm::io::testing {

// A structured n x n triangulation of the unit square classified on 4 points,
// 4 curves and 1 surface, with a physical curve and surface.
inline MeshModel grid_square(int n) {
  MeshModel m;
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.xyz.push_back({double(i) / n, double(j) / n, 0});
  const int corner[4][2] = {{0, 0}, {n, 0}, {n, n}, {0, n}};
  for (int c = 0; c < 4; ++c) {
    EntityMesh p;
    p.dim = 0, p.tag = c + 1, p.type = ElementType::Point1;
    p.nodes = {id(corner[c][0], corner[c][1])};
    p.connectivity = p.nodes;
    m.entities.push_back(p);
  }
  for (int c = 0; c < 4; ++c) {
    EntityMesh e;
    e.dim = 1, e.tag = c + 1, e.type = ElementType::Line2, e.physical_tags = {5};
    e.boundary = {c + 1, -((c + 1) % 4 + 1)};
    const int di = corner[(c + 1) % 4][0] - corner[c][0], dj = corner[(c + 1) % 4][1] - corner[c][1];
    for (int k = 0; k <= n; ++k) {
      const std::uint32_t v = id(corner[c][0] + di / n * k, corner[c][1] + dj / n * k);
      if (k > 0 && k < n) e.nodes.push_back(v), e.params.push_back(double(k) / n);
      if (k > 0) {
        e.connectivity.push_back(id(corner[c][0] + di / n * (k - 1), corner[c][1] + dj / n * (k - 1)));
        e.connectivity.push_back(v);
      }
    }
    m.entities.push_back(e);
  }
  EntityMesh s;
  s.dim = 2, s.tag = 1, s.type = ElementType::Triangle3, s.physical_tags = {7}, s.boundary = {1, 2, 3, 4};
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) s.nodes.push_back(id(i, j)), s.params.push_back(double(i) / n),
                                s.params.push_back(double(j) / n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      for (std::uint32_t v : {id(i, j), id(i + 1, j), id(i + 1, j + 1)}) s.connectivity.push_back(v);
      for (std::uint32_t v : {id(i, j), id(i + 1, j + 1), id(i, j + 1)}) s.connectivity.push_back(v);
    }
  m.entities.push_back(s);
  m.physicals = {{1, 5, "coast"}, {2, 7, "ocean"}};
  return m;
}

// grid_square(n) mapped onto a sphere of `radius` centred at the origin: lon -10..10,
// lat 40..50 (x = 0..1 -> lon, y -> lat), plus a curve across its middle (lat 45,
// tag 5, in the coast group). n must be even.
inline MeshModel sphere_patch(int n, double radius = 1) {
  MeshModel m = grid_square(n);
  for (Vec3& x : m.xyz) {
    const double lon = (-10 + 20 * x.x) * 3.14159265358979323846 / 180;
    const double lat = (40 + 10 * x.y) * 3.14159265358979323846 / 180;
    x = {radius * std::cos(lat) * std::cos(lon), radius * std::cos(lat) * std::sin(lon), radius * std::sin(lat)};
  }
  EntityMesh mid;
  mid.dim = 1, mid.tag = 5, mid.type = ElementType::Line2, mid.physical_tags = {5};
  for (int i = 0; i < n; ++i) {
    mid.connectivity.push_back(std::uint32_t((n / 2) * (n + 1) + i));
    mid.connectivity.push_back(std::uint32_t((n / 2) * (n + 1) + i + 1));
  }
  m.entities.push_back(mid);
  return m;
}

}  // namespace sm::io::testing
