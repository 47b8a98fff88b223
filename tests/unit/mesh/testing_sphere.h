// Test helper: the unit sphere seen through the stereographic projection from
// the South Pole (paper section 3.1). A 60-degree cap round the North Pole as
// a test domain, the plane size delta_u = delta / lambda(u), and measurements
// of a plane triangulation back on the sphere.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <span>

#include "mesh/triangulation.h"
#include "testing_domains.h"

namespace sm::testing {

/// Inverse stereographic map from the South Pole onto the unit sphere.
inline Vec3 unit_on_sphere(Vec2 u) {
  const double r2 = norm2(u);
  return Vec3{2 * u.x / (1 + r2), 2 * u.y / (1 + r2), (1 - r2) / (1 + r2)};
}

/// Plane size for a size `delta` on the sphere: lengths on the sphere are
/// lambda(u) = 2 / (1 + |u|^2) times lengths in the plane (conformal map).
inline std::function<void(std::span<const Vec2>, std::span<double>)> stereo_size(double delta) {
  return [delta](std::span<const Vec2> pts, std::span<double> h) {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = delta * (1 + norm2(pts[i])) / 2;
  };
}

/// The boundary of the cap of angular radius 60 degrees round the North Pole
/// (the circle of radius tan 30 degrees in the plane), cut at about `delta`
/// on the sphere; the cap's area is pi.
inline Loop cap_loop(TriangleStore& m, double delta) {
  const double rho_cap = std::tan(M_PI / 6);
  const int n = static_cast<int>(std::ceil(2 * M_PI * std::sin(M_PI / 3) / delta));
  Loop cap;
  for (int k = 0; k < n; ++k)
    cap.v.push_back(m.add_vertex({rho_cap * std::cos(2 * M_PI * k / n), rho_cap * std::sin(2 * M_PI * k / n)}));
  return cap;
}

/// Equilateral triangles of side delta that tile the cap.
inline double cap_triangles_expected(double delta) { return M_PI / (std::sqrt(3.0) / 4 * delta * delta); }

struct SphereStats {
  double in_07_14 = 0;  // share of edges whose great-circle arc is in [0.7, 1.4] delta
  double rho_09 = 0;    // share of triangles (chords on the sphere) with rho > 0.9
  double area = 0;      // sum of the chord triangles' areas
};

inline SphereStats sphere_stats(const TriangleStore& m, double delta) {
  SphereStats st;
  std::size_t in = 0, total = 0, good = 0;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    const Side o = m.twin[s];
    if (o.valid() && o.value < s) continue;
    const Vec3 a = unit_on_sphere(m.pos(m.org(Side{s}))), b = unit_on_sphere(m.pos(m.dest(Side{s})));
    const double arc = std::atan2(norm(cross(a, b)), dot(a, b));
    in += arc >= 0.7 * delta && arc <= 1.4 * delta;
    ++total;
  }
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    const Vec3 a = unit_on_sphere(m.pos(m.vertex(TriId{t}, 0))), b = unit_on_sphere(m.pos(m.vertex(TriId{t}, 1))),
               c = unit_on_sphere(m.pos(m.vertex(TriId{t}, 2)));
    const double la = norm(b - c), lb = norm(c - a), lc = norm(a - b), ar = 0.5 * norm(cross(b - a, c - a));
    good += 16 * ar * ar / ((la + lb + lc) * la * lb * lc) > 0.9;
    st.area += ar;
  }
  st.in_07_14 = double(in) / double(total);
  st.rho_09 = double(good) / m.num_triangles();
  return st;
}

}  // namespace sm::testing
