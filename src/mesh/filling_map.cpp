// The plane of a non-planar filling Surface (filling_map.h).
#include "mesh/filling_map.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sm {

namespace {

// Chord length of a side of the patch, on 64 samples: enough for the plane's scale,
// which only conditions the map.
double side_length(const geo::PatchSide& s) {
  constexpr int kSamples = 64;
  double len = 0;
  Vec3 prev = s.curve->eval(0.0, s.reversed).p;
  for (int j = 1; j <= kSamples; ++j) {
    const Vec3 q = s.curve->eval(static_cast<double>(j) / kSamples, s.reversed).p;
    len += norm(q - prev);
    prev = q;
  }
  return len;
}

}  // namespace

FillingMap::FillingMap(geo::TransfinitePatch patch) : patch_(std::move(patch)) {
  const auto& s = patch_.sides;
  // 3 sides: Gmsh's triangle u >= v (the old form's square is taken there, param()).
  const bool three = s.size() == 3;
  // The mean of J^T J over a 16 x 16 grid of cell centres (those of Gmsh's triangle
  // u >= v for 3 sides), by central differences.
  constexpr int kMean = 16;
  constexpr double kH = 1e-6;
  double m11 = 0, m12 = 0, m22 = 0;
  int count = 0;
  for (int i = 0; i < kMean; ++i)
    for (int j = 0; j < kMean; ++j) {
      const double u = (i + 0.5) / kMean, v = (j + 0.5) / kMean;
      if (three && v > u) continue;
      const Vec3 xu = (patch_.point(param({u + kH, v})) - patch_.point(param({u - kH, v}))) / (2 * kH);
      const Vec3 xv = (patch_.point(param({u, v + kH})) - patch_.point(param({u, v - kH}))) / (2 * kH);
      m11 += dot(xu, xu), m12 += dot(xu, xv), m22 += dot(xv, xv);
      ++count;
    }
  m11 /= count, m12 /= count, m22 /= count;
  const double det = m11 * m22 - m12 * m12;
  if (m11 > 0 && det > 1e-12 * m11 * m22 && std::isfinite(det)) {
    l11_ = std::sqrt(m11);
    l12_ = m12 / l11_;
    l22_ = std::sqrt(det / m11);
  } else {
    // A degenerate mean metric: the mean lengths of opposite sides (3 sides: the first
    // two), a collapsed pair kept usable.
    double a = s.size() == 3 ? side_length(s[0]) : 0.5 * (side_length(s[0]) + side_length(s[2]));
    double b = s.size() == 3 ? side_length(s[1]) : 0.5 * (side_length(s[1]) + side_length(s[3]));
    const double big = std::max(a, b);
    a = big > 0 ? std::max(a, 1e-3 * big) : 1.0;
    b = big > 0 ? std::max(b, 1e-3 * big) : 1.0;
    l11_ = a, l12_ = 0, l22_ = b;
  }
  step_ = 1e-6 * std::sqrt(l11_ * l22_);
  samples_.reserve((kGrid + 1) * (kGrid + 1));
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      const double u = static_cast<double>(i) / kGrid, v = static_cast<double>(j) / kGrid;
      if (three && v > u) continue;  // Gmsh's triangle u >= v
      const Vec2 p = to_plane({u, v});
      samples_.emplace_back(p, point(p));
    }
}

Vec2 FillingMap::side_point(std::size_t side, double t) const {
  Vec2 uv;
  if (patch_.sides.size() == 4) {
    const Vec2 q[4] = {{t, 0}, {1, t}, {1 - t, 1}, {0, 1 - t}};
    uv = q[side];
  } else {
    const Vec2 q[3] = {{t, 0}, {1, t}, {1 - t, 1 - t}};
    uv = q[side];
  }
  return to_plane(uv);
}

Vec2 FillingMap::param(Vec2 t) const {
  if (patch_.sides.size() != 3 || !patch_.old_style) return t;
  // The old form's square (u, v) seen from the triangle (x, y) = (u, u v): its side u = 0,
  // collapsed to S0 in space, becomes the corner (0, 0), where the form is regular.
  return {t.x, t.x != 0 ? t.y / t.x : 0.0};
}

Vec3 FillingMap::point(Vec2 p) const { return patch_.point(param(to_uv(p))); }

double FillingMap::stretch(Vec2 p) const {
  const double dx = 10 * step_, dy = 10 * step_;
  const Vec3 xu = (point({p.x + dx, p.y}) - point({p.x - dx, p.y})) / (2 * dx);
  const Vec3 xv = (point({p.x, p.y + dy}) - point({p.x, p.y - dy})) / (2 * dy);
  const double area = norm(cross(xu, xv));
  if (area > 0) return std::sqrt(area);
  // A degenerate point of the patch (a collapsed side): the longer tangent.
  const double t = std::max(norm(xu), norm(xv));
  return t > 0 ? t : 1.0;
}

Vec2 FillingMap::plane_of(Vec3 x) const {
  if (const auto it = known_.find({x.x, x.y, x.z}); it != known_.end()) return it->second;
  Vec2 p = samples_.front().first;
  double best = norm2(samples_.front().second - x);
  for (const auto& [q, y] : samples_) {
    const double d = norm2(y - x);
    if (d < best) best = d, p = q;
  }
  // Damped Gauss-Newton on |X(p) - x|^2 with central-difference tangents; the step is
  // halved (at most 30 times) until the distance does not grow.
  const double hx = step_, hy = step_;
  Vec3 r = point(p) - x;
  for (int iter = 0; iter < 40; ++iter) {
    const Vec3 xu = (point({p.x + hx, p.y}) - point({p.x - hx, p.y})) / (2 * hx);
    const Vec3 xv = (point({p.x, p.y + hy}) - point({p.x, p.y - hy})) / (2 * hy);
    const double a = dot(xu, xu), b = dot(xu, xv), c = dot(xv, xv);
    const double det = a * c - b * b;
    if (!(det > 0)) break;
    const double gu = dot(xu, r), gv = dot(xv, r);
    Vec2 step{-(c * gu - b * gv) / det, -(a * gv - b * gu) / det};
    bool moved = false;
    for (int half = 0; half < 30; ++half) {
      const Vec2 q = p + step;
      const Vec3 rq = point(q) - x;
      if (norm2(rq) <= norm2(r)) {
        p = q, r = rq, moved = true;
        break;
      }
      step = 0.5 * step;
    }
    if (!moved || norm(step) < 1e-9 * step_) break;
  }
  return p;
}

}  // namespace sm
