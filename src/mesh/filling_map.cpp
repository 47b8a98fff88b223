// The plane of a non-planar filling Surface (filling_map.h).
#include "mesh/filling_map.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sm {

namespace {

// Chord length of side i of the patch, on 64 samples: enough for the plane's scale,
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
  double a = 0, b = 0;
  if (s.size() == 4) {
    a = 0.5 * (side_length(s[0]) + side_length(s[2]));
    b = 0.5 * (side_length(s[1]) + side_length(s[3]));
  } else {
    a = side_length(s[0]);
    b = side_length(s[1]);
  }
  // A collapsed pair of sides (a patch with a degenerate edge) keeps a usable scale.
  const double big = std::max(a, b);
  scale_ = big > 0 ? Vec2{std::max(a, 1e-3 * big), std::max(b, 1e-3 * big)} : Vec2{1, 1};
  samples_.reserve((kGrid + 1) * (kGrid + 1));
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      const double u = static_cast<double>(i) / kGrid, v = static_cast<double>(j) / kGrid;
      if (s.size() == 3 && v > u) continue;  // Gmsh's triangle u >= v
      const Vec2 p{u * scale_.x, v * scale_.y};
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
  return {uv.x * scale_.x, uv.y * scale_.y};
}

Vec3 FillingMap::point(Vec2 p) const { return patch_.point({p.x / scale_.x, p.y / scale_.y}); }

double FillingMap::stretch(Vec2 p) const {
  const double dx = 1e-5 * scale_.x, dy = 1e-5 * scale_.y;
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
  const double hx = 1e-6 * scale_.x, hy = 1e-6 * scale_.y;
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
    if (!moved || (std::abs(step.x) < 1e-15 * scale_.x && std::abs(step.y) < 1e-15 * scale_.y)) break;
  }
  return p;
}

}  // namespace sm
