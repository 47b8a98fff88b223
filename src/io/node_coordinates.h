// Which coordinates MSH and VTK files give the nodes of a mesh on the sphere:
// 3D Cartesian (Gmsh's, the default), lon/lat degrees, or the stereographic plane.
#pragma once

#include <optional>
#include <string>

#include "base/vec.h"
#include "io/mesh_model.h"

namespace sm::io {

/// The values of Mesh.NodeCoordinates and of `-coords`.
enum class NodeCoordinates {
  Xyz = 0,            // x y z as meshed (on the sphere: 3D Cartesian), as Gmsh writes
  LonLat = 1,         // x = longitude in (-180, 180], y = latitude, degrees; z = 0
  Stereographic = 2,  // x y = Gmsh's PolarSphere (u, v) of the sphere; z = 0
};

/// The sphere a mesh lies on (centre and radius of its surface geometry).
struct SphereFrame {
  Vec3 centre{0, 0, 0};
  double radius = 1;
};

/// Rewrites mesh.xyz in `mode`. `sphere` is the model's sphere, or nullopt for a planar
/// model: lon/lat is then an error (there is no sphere), and the stereographic plane of a
/// planar model is the model plane itself (coordinates unchanged). Model points off the
/// sphere (a PolarSphere's centre) have no lon/lat: their Point entities are left out.
/// Returns "" or why not (a curve or triangle node off the sphere, or at the stereographic
/// map's pole); the mesh is then unchanged. Longitudes are not unwrapped: a triangle
/// across the antimeridian keeps nodes near +180 and -180, as ADCIRC and SCHISM expect.
std::string convert_node_coordinates(MeshModel& mesh, NodeCoordinates mode, const std::optional<SphereFrame>& sphere);

/// "xyz", "lonlat", "stereo" -> the mode; nullopt for any other name.
std::optional<NodeCoordinates> node_coordinates_from_name(const std::string& name);

}  // namespace sm::io
