// The rigid map of a `Periodic Surface` without a transform, and its copy's node
// correspondence (periodic_surface.h).
#include "mesh/periodic_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

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

// A surface's points and curves as Gmsh pairs them: the boundary curves' and embedded
// curves' end points and the embedded points; the boundary curves, then the embedded ones.
struct SurfaceEntities {
  std::vector<int> points;   // sorted, unique
  std::vector<int> curves;   // > 0, unique, in the surface's order
};

SurfaceEntities surface_entities(const geo::Model& model, int tag, bool embedded_only) {
  const geo::ModelSurface& s = *model.surface(tag);
  SurfaceEntities out;
  auto add_curve = [&](int c) {
    const geo::ModelCurve* mc = model.curve(std::abs(c));
    if (!mc || std::find(out.curves.begin(), out.curves.end(), std::abs(c)) != out.curves.end()) return;
    out.curves.push_back(std::abs(c));
    out.points.push_back(mc->begin);
    out.points.push_back(mc->end);
  };
  if (!embedded_only)
    for (int l : s.loops)
      if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
        for (int c : loop->curves) add_curve(c);
  for (int c : s.embedded_curves) add_curve(c);
  for (int p : s.embedded_points)
    if (model.vertex(p)) out.points.push_back(p);
  std::sort(out.points.begin(), out.points.end());
  out.points.erase(std::unique(out.points.begin(), out.points.end()), out.points.end());
  return out;
}

// The bounding box of 33 points of curve c, each mapped by `affine` (none: as they are).
geo::BoundingBox sampled_box(const geo::ModelCurve& c, const std::vector<double>* affine) {
  geo::BoundingBox box;
  constexpr int kSamples = 32;
  for (int i = 0; i <= kSamples; ++i) {
    const Vec3 p = c.shape ? c.shape->point(static_cast<double>(i) / kSamples) : Vec3{};
    box.add(affine ? apply_affine(*affine, p) : p);
  }
  return box;
}

// Whether source curve `sc` mapped by `affine` runs along target curve `tc` as Gmsh tells
// curves with the same end points apart: their bounding boxes' corners within a thousandth
// of the target's box (its bounding boxes are rough; sampled ones are too).
bool same_place(const geo::ModelCurve& tc, const geo::ModelCurve& sc, const std::vector<double>& affine,
                double tolerance) {
  const geo::BoundingBox mine = sampled_box(tc, nullptr), theirs = sampled_box(sc, &affine);
  const double tol = std::max(1e-3 * mine.diagonal(), tolerance);
  return norm(mine.lo - theirs.lo) <= tol && norm(mine.hi - theirs.hi) <= tol;
}

// A closed curve's copy runs alike when the map turns the source's tangent at its start
// along the target's (both curves start at the same place, so their ends tell nothing).
int closed_orientation(const geo::ModelCurve& tc, const geo::ModelCurve& sc, const std::vector<double>& affine) {
  if (!tc.shape || !sc.shape) return 1;
  const Vec3 at = sc.shape->point(0), along = sc.shape->eval(0).d1;
  const Vec3 turned = apply_affine(affine, at + along) - apply_affine(affine, at);
  return dot(turned, tc.shape->eval(0).d1) < 0 ? -1 : 1;
}

}  // namespace

PeriodicSurfaceMatch match_periodic_surface(const geo::Model& model, int target, int source,
                                            const std::vector<double>& affine, double tolerance, bool embedded_only) {
  using Miss = PeriodicSurfaceMatch::Miss;
  PeriodicSurfaceMatch out;
  const SurfaceEntities mine = surface_entities(model, target, embedded_only);
  const SurfaceEntities theirs = surface_entities(model, source, embedded_only);
  if (mine.points.size() != theirs.points.size() || mine.curves.size() != theirs.curves.size()) {
    out.miss = Miss::Counts;
    out.counts[0] = mine.points.size(), out.counts[1] = mine.curves.size();
    out.counts[2] = theirs.points.size(), out.counts[3] = theirs.curves.size();
    return out;
  }
  // Each source point onto the nearest target point (Gmsh takes the first within the
  // tolerance; the nearest is the same one whenever the points are farther apart than that).
  std::map<int, int> source_of;   // target point -> source point
  for (int p : theirs.points) {
    const Vec3 x = apply_affine(affine, model.vertex(p)->xyz);
    int best = 0;
    double best_d = 1e300;
    for (int q : mine.points) {
      const double d = norm(model.vertex(q)->xyz - x);
      if (d < best_d) best = q, best_d = d;
    }
    if (!(best_d <= tolerance)) {
      out.miss = Miss::Point, out.entity = p, out.image = x, out.distance = best_d;
      return out;
    }
    source_of[best] = p;
  }
  for (int c : mine.curves) {
    const geo::ModelCurve& tc = *model.curve(c);
    const auto b = source_of.find(tc.begin), e = source_of.find(tc.end);
    // The source curves whose ends land on c's, with the way they run; one is taken as it
    // is, several (the same end points) are told apart by where they lie.
    std::vector<std::pair<int, int>> candidates;
    for (int sc_tag : theirs.curves) {
      if (b == source_of.end() || e == source_of.end()) break;
      const geo::ModelCurve& sc = *model.curve(sc_tag);
      if (sc.begin == b->second && sc.end == e->second) candidates.emplace_back(sc_tag, 1);
      else if (sc.begin == e->second && sc.end == b->second) candidates.emplace_back(sc_tag, -1);
    }
    if (candidates.size() > 1)
      std::erase_if(candidates, [&](const std::pair<int, int>& k) {
        return !same_place(tc, *model.curve(k.first), affine, tolerance);
      });
    if (candidates.empty()) {
      out.miss = Miss::Curve, out.entity = c;
      return out;
    }
    const auto [found, o] = candidates.front();
    const int orientation = tc.periodic() ? closed_orientation(tc, *model.curve(found), affine) : o;
    out.curves.push_back({c, found, orientation});
  }
  const geo::ModelSurface& s = *model.surface(target);
  for (int p : s.embedded_points)
    if (const auto it = source_of.find(p); it != source_of.end()) out.points.emplace_back(p, it->second);
  return out;
}

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
  for (const auto& [point, counterpart] : spec.points) {
    const auto mine = mesh.vertex_node.find(point), theirs = mesh.vertex_node.find(counterpart);
    if (mine == mesh.vertex_node.end() || theirs == mesh.vertex_node.end()) {
      if (why) {
        why->kind = MeshErrorKind::Failed;
        why->problem = MeshProblem::PeriodicSurfacePointNoNode;
        why->surface = target;
        why->numbers = {point, counterpart};
      }
      return {};
    }
    image[theirs->second] = mine->second;
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
