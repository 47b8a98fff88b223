// A periodic surface's mesh copied from its source's (face_periodic_copy.h).
#include "mesh/face_periodic_copy.h"

#include <cstdlib>
#include <utility>

#include <fmt/format.h>

#include "mesh/periodic_curve.h"
#include "mesh/periodic_surface.h"

namespace sm {

namespace {

// The sign of curve `c` in surface `surface`'s loops as the surface runs them (0 if absent).
int curve_sign_in_surface(const geo::Model& model, int surface, int c) {
  for (int l : model.surface(surface)->loops)
    if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
      for (int k : loop->curves)
        if (std::abs(k) == c) return ((k < 0) != (l < 0)) ? -1 : 1;
  return 0;
}

// Whether the map runs the source's boundary against the target's: the first pair whose
// curves both bound their surfaces decides (the source runs curve s one way, the map takes
// s onto t with the pair's orientation, the target runs t its own way).
bool copy_reverses(const geo::Model& model, int target, const PeriodicSurfaceSpec& spec) {
  for (const PeriodicSurfaceSpec::CurvePair& p : spec.curves) {
    const int in_target = curve_sign_in_surface(model, target, p.target);
    const int in_source = curve_sign_in_surface(model, spec.source, p.source);
    if (in_target != 0 && in_source != 0) return in_source * p.orientation != in_target;
  }
  return false;
}

}  // namespace

bool copy_periodic_face(FaceWork& f, const PeriodicSurfaceSpec& spec) {
  const auto src = f.mesh.surfaces.find(spec.source);
  if (src == f.mesh.surfaces.end())
    return f.fail(MeshProblem::SourceNotMeshed, {spec.source});
  MeshError broke;
  std::map<std::uint32_t, std::uint32_t> image = periodic_boundary_images(f.mesh, f.tag, spec, &broke);
  if (image.empty()) {
    if (broke.ok()) return f.fail(MeshProblem::PairedCurvesNoNodes);
    const auto& n = broke.numbers;
    return f.fail(MeshProblem::PeriodicFaceCurveNodes, {n[0], n[1], n[2], n[3], n[4]});
  }

  const geo::ModelSurface& s = *f.model.surface(f.tag);
  const geo::SurfaceGeometry* geom = s.geometry ? f.model.geometry(s.geometry) : nullptr;
  if (s.geometry && !geom) return f.fail(MeshProblem::GeometryMissing, {s.geometry});
  SurfaceMesh out;
  out.tag = f.tag;
  // Copied before the new nodes are added: the source's list lives in the same map.
  const std::vector<std::uint32_t> source_interior = src->second.interior_nodes;
  for (std::uint32_t v : source_interior) {
    const Vec3 x = apply_affine(spec.affine, f.mesh.nodes[v].xyz);
    std::uint32_t copy = 0;
    if (geom) {
      const Vec2 uv = geom->param(x);   // onto the target's geometry, as Gmsh's parFromPoint
      copy = f.mesh.add_node(geom->point(uv), uv);
    } else {
      copy = f.mesh.add_node(x);
    }
    image[v] = copy;
    out.interior_nodes.push_back(copy);
  }
  const SurfaceMesh& from = f.mesh.surfaces.at(spec.source);
  auto node = [&](std::uint32_t v, std::uint32_t& into) {
    const auto it = image.find(v);
    if (it == image.end()) return false;
    into = it->second;
    return true;
  };
  const bool reverse = copy_reverses(f.model, f.tag, spec);
  for (const auto& t : from.triangles) {
    std::array<std::uint32_t, 3> c{};
    for (int e = 0; e < 3; ++e)
      if (!node(t[e], c[e])) {
        f.fail(MeshProblem::PeriodicNodeOffCurves, {spec.source});
        f.res.error.xyz = f.mesh.nodes[t[e]].xyz;   // in the sentence, not a place after it
        return false;
      }
    if (reverse) std::swap(c[1], c[2]);
    out.triangles.push_back(c);
  }
  for (const auto& q : from.quads) {
    std::array<std::uint32_t, 4> c{};
    for (int e = 0; e < 4; ++e)
      if (!node(q[e], c[e])) return f.fail(MeshProblem::PeriodicQuadNodeOffCurves, {spec.source});
    if (reverse) std::swap(c[1], c[3]);
    out.quads.push_back(c);
  }
  f.mesh.surfaces[f.tag] = std::move(out);
  return true;
}

}  // namespace sm
