// Node coordinates for the writers (see node_coordinates.h).
#include "io/node_coordinates.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "geo/sphere.h"

namespace sm::io {

std::string convert_node_coordinates(MeshModel& mesh, NodeCoordinates mode, const std::optional<SphereFrame>& sphere) {
  if (mode == NodeCoordinates::Xyz) return {};
  if (!sphere) {
    if (mode == NodeCoordinates::LonLat)
      return "lon/lat node coordinates need a mesh on a sphere (PolarSphere or Sphere), and this model is planar";
    return {};
  }
  const geo::PolarSphere s(sphere->centre, sphere->radius);
  auto on_sphere = [&](Vec3 x) { return std::abs(norm(x - sphere->centre) - sphere->radius) <= 1e-6 * sphere->radius; };
  // Model points off the sphere (a PolarSphere's centre) are construction points with no
  // lon/lat: they are left out. Any other node off the sphere is an error.
  std::vector<char> drawn(mesh.xyz.size(), 0);
  for (const EntityMesh& e : mesh.entities)
    if (e.type != ElementType::Point1)
      for (std::uint32_t v : e.connectivity) drawn[v] = 1;
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i)
    if (drawn[i] && !on_sphere(mesh.xyz[i]))
      return fmt::format("node {} ({:g}, {:g}, {:g}) is not on the sphere of centre ({:g}, {:g}, {:g}) and radius {:g}",
                         i + 1, mesh.xyz[i].x, mesh.xyz[i].y, mesh.xyz[i].z, sphere->centre.x, sphere->centre.y,
                         sphere->centre.z, sphere->radius);
  // Convert into a copy so that a failure leaves the mesh as it was.
  std::vector<Vec3> out(mesh.xyz.size(), Vec3{0, 0, 0});
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i) {
    if (!on_sphere(mesh.xyz[i])) continue;   // a construction point, dropped below
    if (mode == NodeCoordinates::LonLat) {
      const geo::LonLat ll = s.to_lonlat(mesh.xyz[i]);
      out[i] = {ll.lon, ll.lat, 0};
    } else {
      const Vec2 uv = s.param(mesh.xyz[i]);   // + 0.0 below: no "-0" in the files
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        const geo::LonLat ll = s.to_lonlat(mesh.xyz[i]);
        return fmt::format("node {} (lon {:.4f}, lat {:.4f}) lies at the pole of the stereographic map: it has no "
                           "stereographic coordinates",
                           i + 1, ll.lon, ll.lat);
      }
      out[i] = {uv.x + 0.0, uv.y + 0.0, 0};
    }
  }
  std::erase_if(mesh.entities, [&](const EntityMesh& e) {
    return e.type == ElementType::Point1 && !e.nodes.empty() && !on_sphere(mesh.xyz[e.nodes[0]]);
  });
  mesh.xyz = std::move(out);
  return {};
}

std::optional<NodeCoordinates> node_coordinates_from_name(const std::string& name) {
  if (name == "xyz") return NodeCoordinates::Xyz;
  if (name == "lonlat") return NodeCoordinates::LonLat;
  if (name == "stereo") return NodeCoordinates::Stereographic;
  return std::nullopt;
}

}  // namespace sm::io
