// The plane a face is meshed in (face_plane.h): the pole check of a Mercator plane, the
// Newell normal and planarity check of a Plane Surface.
#include "mesh/face_plane.h"

#include <algorithm>

namespace sm {

geo::LonLat FacePlane::lonlat(Vec3 x) const {
  if (geom->polar()) return geom->polar()->to_lonlat(x);
  const Vec2 uv = geom->param(x);
  return {uv.x * geo::kRadToDeg, uv.y * geo::kRadToDeg};
}

std::optional<FacePlaneProblem> make_face_plane(FacePlane& plane, const ModelMesh& mesh,
                                                std::span<const std::vector<std::uint32_t>* const> curves,
                                                std::span<const std::uint32_t> points, double tolerance,
                                                double accept, std::optional<FacePlaneOffset>* offset) {
  if (plane.geom) {
    plane.mercator = plane.geom->lonlat() != nullptr;
    Vec2 uv{0, 0};
    for (const std::vector<std::uint32_t>* nodes : curves)
      for (std::uint32_t v : *nodes) {
        uv = plane.node_param(mesh.nodes[v]);
        if (plane.mercator && !(std::abs(uv.y) < 0.5 * geo::kPi - 1e-9))
          return FacePlaneProblem{FacePlaneFault::AtPole, mesh.nodes[v].xyz};
      }
    uv = plane.node_param(mesh.nodes[curves[0]->front()]);
    Vec3 du, dv;
    plane.geom->tangents(uv, du, dv);
    // Mercator keeps the orientation of (lon, lat): dy/dlat = 1 / cos lat > 0.
    plane.ccw_is_outward = dot(cross(du, dv), plane.geom->point(uv) - plane.geom->centre()) > 0;
    return std::nullopt;
  }
  // Newell's normal of the outer loop and its centroid.
  Vec3 n{0, 0, 0}, c{0, 0, 0};
  const std::vector<std::uint32_t>& L = *curves[0];
  for (std::size_t i = 0; i < L.size(); ++i) {
    const Vec3 a = mesh.nodes[L[i]].xyz, b = mesh.nodes[L[(i + 1) % L.size()]].xyz;
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    c = c + a;
  }
  c = c / static_cast<double>(L.size());
  const double nn = norm(n);
  if (!(nn > 0)) return FacePlaneProblem{FacePlaneFault::NoArea, mesh.nodes[L[0]].xyz};
  n = n / nn;
  if (n.x == 0 && n.y == 0) {
    plane.o = {0, 0, c.z};
    plane.e1 = {1, 0, 0};
    plane.e2 = {0, n.z > 0 ? 1.0 : -1.0, 0};
    plane.n = {0, 0, n.z > 0 ? 1.0 : -1.0};
    plane.o.z = mesh.nodes[L[0]].xyz.z;
  } else {
    const Vec3 axis = std::abs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    plane.e1 = cross(axis, n);
    plane.e1 = plane.e1 / norm(plane.e1);
    plane.e2 = cross(n, plane.e1);
    plane.o = c;
    plane.n = n;
  }
  // Within the tolerance a node is in the plane; up to `accept` it is off but accepted (the
  // farthest such node is reported); beyond, the face is not planar.
  const double bound = std::max(tolerance, accept);
  FacePlaneOffset farthest;
  auto check = [&](std::uint32_t node) {
    const Vec3 x = mesh.nodes[node].xyz;
    const double d = std::abs(dot(x - plane.o, plane.n));
    if (d > tolerance && d > farthest.distance) farthest = {d, x};
    return d <= bound;
  };
  for (const std::vector<std::uint32_t>* nodes : curves)
    for (std::uint32_t v : *nodes)
      if (!check(v)) return FacePlaneProblem{FacePlaneFault::NotPlanar, mesh.nodes[v].xyz};
  for (std::uint32_t v : points)
    if (!check(v)) return FacePlaneProblem{FacePlaneFault::PointOffPlane, mesh.nodes[v].xyz};
  if (offset && farthest.distance > 0) *offset = farthest;
  return std::nullopt;
}

}  // namespace sm
