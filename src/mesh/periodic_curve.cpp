// Periodic curves: maps, the end-point check and the copied nodes (periodic_curve.h).
#include "mesh/periodic_curve.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "mesh/periodic_surface.h"

namespace sm {

std::vector<double> periodic_translation(Vec3 d) {
  return {1, 0, 0, d.x, 0, 1, 0, d.y, 0, 0, 1, d.z, 0, 0, 0, 1};
}

std::vector<double> periodic_rotation(Vec3 axis, Vec3 point, double angle) {
  const double len = norm(axis);
  if (!(len > 0) || !std::isfinite(len)) return {};
  const Vec3 u = axis / len;
  const double c = std::cos(angle), s = std::sin(angle);
  // Rodrigues' rotation matrix R, then the translation point - R point that keeps the
  // axis in place.
  const double r[3][3] = {{c + u.x * u.x * (1 - c), u.x * u.y * (1 - c) - u.z * s, u.x * u.z * (1 - c) + u.y * s},
                          {u.x * u.y * (1 - c) + u.z * s, c + u.y * u.y * (1 - c), u.y * u.z * (1 - c) - u.x * s},
                          {u.x * u.z * (1 - c) - u.y * s, u.y * u.z * (1 - c) + u.x * s, c + u.z * u.z * (1 - c)}};
  const double p[3] = {point.x, point.y, point.z};
  std::vector<double> a(16, 0.0);
  for (int i = 0; i < 3; ++i) {
    double t = p[i];
    for (int j = 0; j < 3; ++j) {
      a[4 * i + j] = r[i][j];
      t -= r[i][j] * p[j];
    }
    a[4 * i + 3] = t;
  }
  a[15] = 1;
  return a;
}

Vec3 apply_affine(const std::vector<double>& a, Vec3 p) {
  return {a[0] * p.x + a[1] * p.y + a[2] * p.z + a[3], a[4] * p.x + a[5] * p.y + a[6] * p.z + a[7],
          a[8] * p.x + a[9] * p.y + a[10] * p.z + a[11]};
}

std::optional<int> periodic_orientation(const geo::Model& model, int target, int source,
                                        const std::vector<double>& affine, double tolerance,
                                        std::pair<double, double>* distances) {
  const geo::ModelCurve* t = model.curve(target);
  const geo::ModelCurve* s = model.curve(source);
  if (!t || !s) return std::nullopt;
  const geo::ModelVertex *tb = model.vertex(t->begin), *te = model.vertex(t->end);
  const geo::ModelVertex *sb = model.vertex(s->begin), *se = model.vertex(s->end);
  if (!tb || !te || !sb || !se) return std::nullopt;
  const Vec3 mb = apply_affine(affine, sb->xyz), me = apply_affine(affine, se->xyz);
  const double d00 = norm(tb->xyz - mb), d11 = norm(te->xyz - me);
  const double d01 = norm(tb->xyz - me), d10 = norm(te->xyz - mb);
  // As Gmsh: the pairing begin-begin first (a closed curve matches both ways).
  if (d00 < tolerance && d11 < tolerance) return 1;
  if (d01 < tolerance && d10 < tolerance) return -1;
  if (distances) *distances = d00 * d11 < d01 * d10 ? std::pair{d00, d11} : std::pair{d01, d10};
  return std::nullopt;
}

namespace {

// The parameter of curve c's point nearest p, from the guess t0: Newton's steps on
// (X(t) - p) . X'(t) = 0 (at most 30, clamped to [0, 1]); when they end away from p, the
// best of 64 samples per polynomial piece starts them again. Bounded by construction.
double nearest_parameter(const geo::Curve& c, Vec3 p, double t0, double tolerance) {
  auto newton = [&](double t) {
    for (int it = 0; it < 30; ++it) {
      const geo::Jet3 j = c.eval(t);
      const Vec3 d = j.p - p;
      const double f = dot(d, j.d1), df = norm2(j.d1) + dot(d, j.d2);
      if (!(df > 0)) break;
      const double next = std::clamp(t - f / df, 0.0, 1.0);
      if (std::fabs(next - t) < 1e-15) return next;
      t = next;
    }
    return t;
  };
  double t = newton(t0);
  if (norm(c.point(t) - p) <= tolerance) return t;
  const int n = 64 * std::max(1, c.pieces());
  double best = t, best_d = norm(c.point(t) - p);
  for (int i = 0; i <= n; ++i) {
    const double ti = static_cast<double>(i) / n;
    const double d = norm(c.point(ti) - p);
    if (d < best_d) best = ti, best_d = d;
  }
  const double refined = newton(best);
  return norm(c.point(refined) - p) < best_d ? refined : best;
}

}  // namespace

bool periodic_curve_nodes(const geo::Model& model, const ModelMesh& mesh, int target, const PeriodicCurveSpec& spec,
                          std::vector<double>& ts, std::vector<Vec3>& xyz, MeshError* why) {
  auto fail = [&](MeshProblem problem, std::array<long long, 5> numbers) {
    if (!why) return false;
    why->kind = MeshErrorKind::Invalid;
    why->problem = problem;
    why->add_entity(1, target);
    why->add_entity(1, spec.source);
    why->numbers = numbers;
    return false;
  };
  const geo::ModelCurve* mc = model.curve(target);
  const auto src = mesh.curves.find(spec.source);
  if (!mc || !mc->shape || src == mesh.curves.end() || src->second.nodes.size() < 2) {
    return fail(MeshProblem::PeriodicSourceNotMeshed, {target, spec.source});
  }
  const CurveMesh& s = src->second;
  const std::size_t n = s.nodes.size();
  const geo::Curve& shape = *mc->shape;
  const double tolerance = 1e-9 * std::max(1.0, model.bounding_box().diagonal());
  ts.assign(n, 0.0);
  ts.back() = 1.0;
  xyz.clear();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const std::size_t k = spec.orientation > 0 ? i : n - 1 - i;
    const double guess = spec.orientation > 0 ? s.t[k] : 1.0 - s.t[k];
    ts[i] = spec.affine.empty()
                ? guess
                : nearest_parameter(shape, apply_affine(spec.affine, mesh.nodes[s.nodes[k]].xyz), guess, tolerance);
    xyz.push_back(shape.point(ts[i]));
  }
  for (std::size_t i = 1; i < n; ++i)
    if (!(ts[i] > ts[i - 1]))
      return fail(MeshProblem::PeriodicCopyNotAlong,
                  {target, spec.source, static_cast<long long>(i), static_cast<long long>(n - 1)});
  return true;
}

std::vector<PeriodicLink> periodic_links(const geo::Model& model, const ModelMesh& mesh, const MeshConstraints& c,
                                         MeshError* why) {
  std::vector<PeriodicLink> out;
  for (const auto& [tag, p] : c.periodic_points) {
    const auto a = mesh.vertex_node.find(tag), b = mesh.vertex_node.find(p.master);
    if (a == mesh.vertex_node.end() || b == mesh.vertex_node.end()) continue;
    out.push_back({0, tag, p.master, p.affine, {{a->second, b->second}}});
  }
  for (const auto& [tag, p] : c.periodic_curves) {
    if (!model.curve(tag)) continue;
    const std::vector<std::uint32_t> mine = mesh.curve_nodes(tag);
    const std::vector<std::uint32_t> theirs = mesh.curve_nodes(p.orientation > 0 ? p.source : -p.source);
    if (mine.size() != theirs.size() || mine.size() < 2) {
      if (why && why->ok()) {
        why->kind = MeshErrorKind::Failed;
        why->problem = MeshProblem::PeriodicCurveNodeCounts;
        why->numbers = {tag, static_cast<long long>(mine.size()), p.source, static_cast<long long>(theirs.size())};
      }
      continue;
    }
    PeriodicLink l{1, tag, p.source, p.affine, {}};
    for (std::size_t i = 0; i < mine.size(); ++i) l.nodes.emplace_back(mine[i], theirs[i]);
    out.push_back(std::move(l));
  }
  std::vector<PeriodicLink> surfaces = periodic_surface_links(mesh, c, why);
  for (PeriodicLink& l : surfaces) out.push_back(std::move(l));
  return out;
}

}  // namespace sm
