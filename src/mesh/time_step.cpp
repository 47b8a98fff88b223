// Courant time step of a mesh (see time_step.h).
#include "mesh/time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

double time_step_edge_length(Vec3 a, Vec3 b, const TimeStepOptions& opt) { return edge_length(a, b, opt); }

void time_step_lonlat(Vec3 x, const TimeStepOptions& opt, double& lon, double& lat) {
  const Vec3 p = x - opt.centre;
  const double deg = 180 / std::numbers::pi;
  lon = std::atan2(p.y, p.x) * deg;
  lat = std::atan2(p.z, std::hypot(p.x, p.y)) * deg;
}

double triangle_time_step(Vec3 a, Vec3 b, Vec3 c, double da, double db, double dc, const TimeStepOptions& opt) {
  const double h = std::max({opt.min_depth, da, db, dc});
  if (!(h > 0)) return std::numeric_limits<double>::infinity();
  const double e = std::min({edge_length(a, b, opt), edge_length(b, c, opt), edge_length(c, a, opt)});
  return e / std::sqrt(opt.gravity * h);
}

std::vector<double> triangle_time_steps(const ModelMesh& mesh, std::span<const double> node_depth,
                                        const TimeStepOptions& opt) {
  std::vector<double> out;
  auto depth = [&](std::uint32_t v) { return v < node_depth.size() ? node_depth[v] : 0.0; };
  for (const auto& [tag, sf] : mesh.surfaces)
    for (const auto& t : sf.triangles)
      out.push_back(triangle_time_step(mesh.nodes[t[0]].xyz, mesh.nodes[t[1]].xyz, mesh.nodes[t[2]].xyz,
                                       depth(t[0]), depth(t[1]), depth(t[2]), opt));
  return out;
}

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
  std::vector<double> steps = triangle_time_steps(mesh, node_depth, opt);
  std::erase_if(steps, [](double x) { return !std::isfinite(x); });
  best.wet = steps.size();
  if (!steps.empty()) {
    const auto k = static_cast<std::ptrdiff_t>((steps.size() - 1) / 100);
    std::nth_element(steps.begin(), steps.begin() + k, steps.end());
    best.q01 = steps[static_cast<std::size_t>(k)];
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
