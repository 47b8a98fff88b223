// ModelMesh -> MeshModel: classification, boundaries and physical groups as Gmsh writes
// them (gmsh-reference 7.2).
#include "io/from_model_mesh.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <utility>

namespace sm::io {

MeshModel from_model_mesh(const geo::Model& model, const ModelMesh& mesh) {
  MeshModel out;
  out.xyz.reserve(mesh.nodes.size());
  for (const MeshNode& n : mesh.nodes) out.xyz.push_back(n.xyz);
  // (dim, |entity tag|) -> physical tags, ascending and without repeats.
  std::map<std::pair<int, int>, std::vector<int>> groups_of;
  for (const auto& [key, g] : model.physicals()) {
    out.physicals.push_back({g.dim, g.tag, g.name});
    for (int e : g.entities) {
      std::vector<int>& v = groups_of[{g.dim, std::abs(e)}];
      if (v.empty() || v.back() != g.tag) v.push_back(g.tag);
    }
  }
  auto physicals = [&](int dim, int tag) {
    const auto it = groups_of.find({dim, tag});
    return it == groups_of.end() ? std::vector<int>{} : it->second;
  };
  out.entities.reserve(mesh.vertex_node.size() + mesh.curves.size() + model.surfaces().size());
  for (const auto& [tag, node] : mesh.vertex_node) {
    EntityMesh e;
    e.dim = 0, e.tag = tag, e.type = ElementType::Point1;
    e.physical_tags = physicals(0, tag);
    e.nodes = {node};
    e.connectivity = {node};
    out.entities.push_back(std::move(e));
  }
  for (const auto& [tag, c] : mesh.curves) {
    const geo::ModelCurve* mc = model.curve(tag);
    EntityMesh e;
    e.dim = 1, e.tag = tag, e.type = ElementType::Line2;
    e.physical_tags = physicals(1, tag);
    if (mc) e.boundary = {mc->begin, -mc->end};
    for (std::size_t k = 1; k + 1 < c.nodes.size(); ++k) {
      e.nodes.push_back(c.nodes[k]);
      e.params.push_back(c.t[k]);
    }
    e.connectivity.reserve(2 * c.num_edges());
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) {
      e.connectivity.push_back(c.nodes[k]);
      e.connectivity.push_back(c.nodes[k + 1]);
    }
    out.entities.push_back(std::move(e));
  }
  for (const auto& [tag, s] : model.surfaces()) {
    EntityMesh e;
    e.dim = 2, e.tag = tag, e.type = ElementType::Triangle3;
    e.physical_tags = physicals(2, tag);
    for (int l : s.loops) {
      const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l));
      if (!loop) continue;
      if (l > 0) {
        e.boundary.insert(e.boundary.end(), loop->curves.begin(), loop->curves.end());
      } else {
        for (auto it = loop->curves.rbegin(); it != loop->curves.rend(); ++it) e.boundary.push_back(-*it);
      }
    }
    const auto it = mesh.surfaces.find(tag);
    if (it != mesh.surfaces.end()) {
      const SurfaceMesh& sm = it->second;
      e.nodes = sm.interior_nodes;
      const bool uv = std::all_of(sm.interior_nodes.begin(), sm.interior_nodes.end(),
                                  [&](std::uint32_t n) { return mesh.nodes[n].has_uv; });
      if (uv)
        for (std::uint32_t n : sm.interior_nodes) e.params.insert(e.params.end(), {mesh.nodes[n].uv.x, mesh.nodes[n].uv.y});
      for (const auto& t : sm.triangles) e.connectivity.insert(e.connectivity.end(), t.begin(), t.end());
      if (!sm.quads.empty()) {
        // Quadrangles only: the entity's one block is theirs. Both kinds: a second record of
        // the same entity holds the quadrangles (no nodes: the first owns them), as MSH 4.1
        // writes a block per element type.
        EntityMesh q;
        q.dim = 2, q.tag = tag, q.type = ElementType::Quad4;
        q.physical_tags = e.physical_tags;
        q.boundary = e.boundary;
        for (const auto& f : sm.quads) q.connectivity.insert(q.connectivity.end(), f.begin(), f.end());
        if (sm.triangles.empty()) {
          e.type = ElementType::Quad4;
          e.connectivity = std::move(q.connectivity);
        } else {
          out.entities.push_back(std::move(e));
          out.entities.push_back(std::move(q));
          continue;
        }
      }
    }
    out.entities.push_back(std::move(e));
  }
  return out;
}

}  // namespace sm::io
