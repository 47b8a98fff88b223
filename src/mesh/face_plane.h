// The plane a face is meshed in: a PolarSphere's stereographic (u,v), a lon/lat Sphere's
// Mercator plane, or for a Plane Surface its own plane with an orthonormal basis; maps
// between that plane, the surface parameters and space, and the conformal factor.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/vec.h"
#include "geo/sphere.h"
#include "geo/surface_geometry.h"
#include "mesh/filling_map.h"
#include "mesh/model_mesh.h"

namespace sm {

// A lon/lat Sphere's Mercator plane is (x, y) = (lon, asinh(tan lat)), conformal with
// factor r cos lat = r / cosh y, so the anisotropic metric J^T J = diag(r^2 cos^2 lat, r^2)
// of (lon, lat) becomes isotropic and the same refiners apply. A Euclidean plane gets an
// orthonormal basis (e1, e2) such that e1 x e2 is the outer loop's Newell normal, so the
// outer loop runs counter-clockwise in the plane; for a loop in z = const the basis is
// (x, +-y) and the coordinates are exact. A non-planar filling Surface is meshed in the
// scaled parameters of its patch (filling_map.h).
struct FacePlane {
  const geo::SurfaceGeometry* geom = nullptr;
  std::shared_ptr<const FillingMap> filling;  // set: the plane is the patch's (geom null)
  bool mercator = false;
  Vec3 o, e1, e2, n;
  bool ccw_is_outward = true;   // on a geometry: counter-clockwise triangles face outwards

  Vec2 to_plane(Vec3 x) const { return {dot(x - o, e1), dot(x - o, e2)}; }
  /// Plane point of surface parameters (u,v) (lon/lat in radians on a Sphere).
  Vec2 from_param(Vec2 uv) const { return mercator ? Vec2{uv.x, std::asinh(std::tan(uv.y))} : uv; }
  /// Surface parameters of a plane point.
  Vec2 to_param(Vec2 p) const { return mercator ? Vec2{p.x, std::atan(std::sinh(p.y))} : p; }
  Vec3 to_space(Vec2 p) const {
    if (filling) return filling->point(p);
    return geom ? geom->point(to_param(p)) : o + p.x * e1 + p.y * e2;
  }
  /// Lengths on the surface per length in the plane at p (1 on a Euclidean plane).
  double lambda(Vec2 p) const {
    if (filling) return filling->stretch(p);
    if (!geom) return 1.0;
    if (const geo::PolarSphere* ps = geom->polar()) return ps->lambda(p);
    return geom->radius() / std::cosh(p.y);
  }
  /// On a geometry: the node's surface parameters (its (u,v), else from its position).
  Vec2 node_param(const MeshNode& node) const { return node.has_uv ? node.uv : geom->param(node.xyz); }
  /// The node's place in the plane.
  Vec2 node_plane(const MeshNode& node) const {
    if (filling) return filling->plane_of(node.xyz);
    return geom ? from_param(node_param(node)) : to_plane(node.xyz);
  }
  /// Plane point of a 3D point (taken radially onto a sphere first).
  Vec2 plane_of_space(Vec3 x) const {
    if (filling) return filling->plane_of(x);
    return geom ? from_param(geom->param(x)) : to_plane(x);
  }
  /// Whether plane lengths differ from lengths on the surface (lambda is not 1).
  bool scaled() const { return geom || filling; }
  /// On a geometry: the longitude/latitude (degrees) of a point of the face.
  geo::LonLat lonlat(Vec3 x) const;
};

/// Why a face has no plane: a lon/lat Sphere face reaching a pole, an outer loop with no
/// area, a boundary node or an embedded point off the plane.
enum class FacePlaneFault { AtPole, NoArea, NotPlanar, PointOffPlane };

/// Why a face has no plane, and the node where it shows.
struct FacePlaneProblem {
  FacePlaneFault fault;
  Vec3 where;
};

/// Sets `plane` up for a face whose boundary and embedded curves are the node chains
/// `curves` (`curves[0]` the outer loop) and whose embedded points are `points`. On a
/// geometry (plane.geom set by the caller) no curve node may reach a pole of a lon/lat
/// Sphere; on a Euclidean plane the outer loop must enclose an area and every node must
/// lie within `tolerance` of the plane (Gmsh's Plane Surface is planar).
/// How far a Plane Surface's boundary lies off the plane it is meshed in, when it is off by
/// more than the tolerance but within the accepted bound (make_face_plane).
struct FacePlaneOffset {
  double distance = 0;
  Vec3 where;
};

/// The plane of a face. Boundary nodes and embedded points farther than `tolerance` from a
/// Plane Surface's plane are a problem unless within `accept` (>= tolerance): then the face is
/// meshed in that plane all the same, its new nodes on it, as Gmsh meshes a Plane Surface in
/// its mean plane, and `offset` (when given) says how far and where.
std::optional<FacePlaneProblem> make_face_plane(FacePlane& plane, const ModelMesh& mesh,
                                                std::span<const std::vector<std::uint32_t>* const> curves,
                                                std::span<const std::uint32_t> points, double tolerance,
                                                double accept = 0,
                                                std::optional<FacePlaneOffset>* offset = nullptr);

}  // namespace sm
