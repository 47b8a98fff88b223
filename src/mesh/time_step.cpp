// Courant time step of a mesh (see time_step.h).
#include "mesh/time_step.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sm {

namespace {

// Length of the edge a-b: on the sphere the great-circle arc (atan2 of the cross and
// dot products keeps short arcs accurate), else the chord.
double edge_length(Vec3 a, Vec3 b, const TimeStepOptions& o) {
  if (!(o.radius > 0)) return norm(b - a);
  const Vec3 p = a - o.centre, q = b - o.centre;
  return o.radius * std::atan2(norm(cross(p, q)), dot(p, q));
}

}  // namespace

TimeStep courant_time_step(const ModelMesh& mesh, std::span<const double> node_depth,
                           const TimeStepOptions& opt) {
  TimeStep best;
  for (const auto& [tag, sf] : mesh.surfaces) {
    for (const auto& t : sf.triangles) {
      double h = opt.min_depth;
      for (std::uint32_t v : t)
        if (v < node_depth.size() && node_depth[v] > h) h = node_depth[v];
      if (!(h > 0)) continue;
      const Vec3 a = mesh.nodes[t[0]].xyz, b = mesh.nodes[t[1]].xyz, c = mesh.nodes[t[2]].xyz;
      const double e = std::min({edge_length(a, b, opt), edge_length(b, c, opt), edge_length(c, a, opt)});
      const double dt = e / std::sqrt(opt.gravity * h);
      if (best.valid && !(dt < best.dt)) continue;
      best.valid = true;
      best.dt = dt;
      best.edge = e;
      best.depth = h;
      best.surface = tag;
      best.where = (a + b + c) / 3.0;
    }
  }
  if (best.valid && opt.radius > 0) {
    const Vec3 p = best.where - opt.centre;
    const double deg = 180 / std::numbers::pi;
    best.has_lonlat = true;
    best.lon = std::atan2(p.y, p.x) * deg;
    best.lat = std::atan2(p.z, std::hypot(p.x, p.y)) * deg;
  }
  return best;
}

}  // namespace sm
