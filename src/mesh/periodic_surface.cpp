// The rigid map of a `Periodic Surface` without a transform, and its copy's node
// correspondence (periodic_surface.h).
#include "mesh/periodic_surface.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mesh/periodic_curve.h"

namespace sm {

namespace {

// The rotation part R (row by row) taking the orthonormal frame built on a1, a2 onto the
// one built on b1, b2 (R = V U^T): a rotation by construction, whatever the rounding.
std::vector<double> frame_rotation(Vec3 a1, Vec3 a2, Vec3 b1, Vec3 b2) {
  auto frame = [](Vec3 x, Vec3 y, Vec3 f[3]) {
    f[0] = x / norm(x);
    const Vec3 y_perp = y - dot(y, f[0]) * f[0];
    f[1] = y_perp / norm(y_perp);
    f[2] = cross(f[0], f[1]);
  };
  Vec3 u[3], v[3];
  frame(a1, a2, u);
  frame(b1, b2, v);
  std::vector<double> r(9, 0.0);
  const auto c = [](Vec3 p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[3 * i + j] += c(v[k], i) * c(u[k], j);
  return r;
}

}  // namespace

std::vector<double> infer_periodic_transform(const std::vector<std::pair<Vec3, Vec3>>& pairs, double tolerance,
                                             std::string* why) {
  auto fail = [&](std::string text) {
    if (why) *why = std::move(text);
    return std::vector<double>{};
  };
  if (pairs.empty()) return fail("the paired curves have no end points");
  const Vec3 d0 = pairs[0].second - pairs[0].first;
  bool translation = true, moved = false;
  for (const auto& [p, q] : pairs) {
    if (norm((q - p) - d0) > tolerance) translation = false;
    if (norm(q - p) > tolerance) moved = true;
  }
  if (!moved) return fail("the paired curves' end points are the same points: the surface would map onto itself");
  if (translation) return periodic_translation(d0);

  // A rotation: fitted on the longest difference a1 = p_i - p_0 and the one farthest from
  // its line, a2, with their images b1, b2 (differences drop the rotation's centre).
  const Vec3 p0 = pairs[0].first, q0 = pairs[0].second;
  std::size_t i1 = 0, i2 = 0;
  for (std::size_t i = 1; i < pairs.size(); ++i)
    if (norm(pairs[i].first - p0) > norm(pairs[i1].first - p0)) i1 = i;
  const Vec3 a1 = pairs[i1].first - p0;
  double off_line = 0;
  for (std::size_t i = 1; i < pairs.size() && i1 != 0; ++i) {
    const double d = norm(cross(a1, pairs[i].first - p0)) / norm(a1);
    if (d > off_line) off_line = d, i2 = i;
  }
  if (i1 == 0 || !(off_line > tolerance))
    return fail("the paired curves' end points lie on one line, which fixes no rotation");
  const Vec3 b1 = pairs[i1].second - q0;
  const Vec3 b2 = pairs[i2].second - q0, a2 = pairs[i2].first - p0;
  if (!(norm(cross(b1, b2)) > 0)) return fail("the paired end points' images lie on one line: no rotation maps them");
  const std::vector<double> r = frame_rotation(a1, a2, b1, b2);
  std::vector<double> affine(16, 0.0);
  const double p[3] = {p0.x, p0.y, p0.z}, q[3] = {q0.x, q0.y, q0.z};
  for (int i = 0; i < 3; ++i) {
    double t = q[i];
    for (int j = 0; j < 3; ++j) {
      affine[4 * i + j] = r[3 * i + j];
      t -= r[3 * i + j] * p[j];
    }
    affine[4 * i + 3] = t;
  }
  affine[15] = 1;
  for (const auto& [a, b] : pairs) {
    const double miss = norm(apply_affine(affine, a) - b);
    if (!(miss <= tolerance))
      return fail(fmt::format("neither a translation nor a rotation maps the paired curves' end points onto "
                              "each other (the best rotation misses one by {:g}, beyond the tolerance {:g})",
                              miss, tolerance));
  }
  return affine;
}

std::map<std::uint32_t, std::uint32_t> periodic_boundary_images(const ModelMesh& mesh, int target,
                                                                 const PeriodicSurfaceSpec& spec, MeshError* why) {
  std::map<std::uint32_t, std::uint32_t> image;
  for (const PeriodicSurfaceSpec::CurvePair& p : spec.curves) {
    const std::vector<std::uint32_t> mine = mesh.curve_nodes(p.target);
    const std::vector<std::uint32_t> theirs = mesh.curve_nodes(p.orientation > 0 ? p.source : -p.source);
    if (mine.size() != theirs.size() || mine.size() < 2) {
      if (why) {
        why->kind = MeshErrorKind::Failed;
        why->problem = MeshProblem::PeriodicSurfaceNodeCounts;
        why->surface = target;
        why->numbers = {p.target, static_cast<long long>(mine.size()), p.source,
                        static_cast<long long>(theirs.size()), spec.source};
      }
      return {};
    }
    for (std::size_t i = 0; i < mine.size(); ++i) image[theirs[i]] = mine[i];
  }
  return image;
}

std::vector<PeriodicLink> periodic_surface_links(const ModelMesh& mesh, const MeshConstraints& c, MeshError* why) {
  std::vector<PeriodicLink> out;
  for (const auto& [tag, spec] : c.periodic_surfaces) {
    const auto mine = mesh.surfaces.find(tag), theirs = mesh.surfaces.find(spec.source);
    if (mine == mesh.surfaces.end() || theirs == mesh.surfaces.end()) continue;
    MeshError broke;
    std::map<std::uint32_t, std::uint32_t> image = periodic_boundary_images(mesh, tag, spec, &broke);
    if (image.empty() || mine->second.interior_nodes.size() != theirs->second.interior_nodes.size()) {
      if (why && why->ok()) {
        if (broke.ok()) {
          broke.kind = MeshErrorKind::Failed;
          broke.problem = MeshProblem::PeriodicSurfaceNotCopy;
          broke.surface = tag;
          broke.numbers[0] = spec.source;
        }
        *why = std::move(broke);
      }
      continue;
    }
    for (std::size_t i = 0; i < mine->second.interior_nodes.size(); ++i)
      image[theirs->second.interior_nodes[i]] = mine->second.interior_nodes[i];
    PeriodicLink l{2, tag, spec.source, spec.affine, {}};
    for (const auto& [source_node, node] : image) l.nodes.emplace_back(node, source_node);
    std::sort(l.nodes.begin(), l.nodes.end());
    out.push_back(std::move(l));
  }
  return out;
}

}  // namespace sm
