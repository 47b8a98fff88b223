// Discrete surfaces into the mesh (discrete_mesh.h).
#include "mesh/discrete_mesh.h"

namespace sm {

MeshError add_discrete_surfaces(const DiscreteEntities& d, ModelMesh& mesh) {
  std::map<std::uint64_t, std::uint32_t> node_of;   // the file's tag -> the mesh's node
  for (const auto& [v, tag] : d.vertex_node)
    if (const auto it = mesh.vertex_node.find(v); it != mesh.vertex_node.end()) node_of.emplace(tag, it->second);
  for (const auto& [c, tags] : d.curve_nodes) {
    const auto it = mesh.curves.find(c);
    if (it == mesh.curves.end()) continue;
    if (it->second.nodes.size() != tags.size()) {
      MeshError e;
      e.kind = MeshErrorKind::Failed;
      e.problem = MeshProblem::DiscreteCurveChanged;
      e.add_entity(1, c);
      e.numbers = {c, static_cast<long long>(it->second.nodes.size()), static_cast<long long>(tags.size())};
      return e;
    }
    for (std::size_t i = 0; i < tags.size(); ++i) node_of.emplace(tags[i], it->second.nodes[i]);
  }
  for (const auto& [s, surface] : d.surfaces) {
    SurfaceMesh& out = mesh.surfaces[s];
    out = SurfaceMesh{};
    out.tag = s;
    auto node = [&](std::uint64_t tag) {
      const auto [it, fresh] = node_of.emplace(tag, 0);
      if (fresh) {
        it->second = mesh.add_node(d.nodes.at(tag));
        out.interior_nodes.push_back(it->second);
      }
      return it->second;
    };
    for (const auto& t : surface.triangles) out.triangles.push_back({node(t[0]), node(t[1]), node(t[2])});
    for (const auto& q : surface.quads) out.quads.push_back({node(q[0]), node(q[1]), node(q[2]), node(q[3])});
  }
  return {};
}

}  // namespace sm
