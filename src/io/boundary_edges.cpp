// Boundary edges of a mesh model (see boundary_edges.h).
#include "io/boundary_edges.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace sm::io {

std::vector<BoundaryEdge> boundary_edges(const MeshModel& m) {
  using Edge = std::pair<std::uint32_t, std::uint32_t>;
  auto key = [](std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; };
  std::map<Edge, int> faces_on;
  std::vector<const EntityMesh*> curves;
  for (const EntityMesh& e : m.entities) {
    if (e.dim == 2 && (e.type == ElementType::Triangle3 || e.type == ElementType::Quad4)) {
      const std::size_t k = static_cast<std::size_t>(nodes_per_element(e.type));
      for (std::size_t i = 0; i + k <= e.connectivity.size(); i += k)
        for (std::size_t j = 0; j < k; ++j) ++faces_on[key(e.connectivity[i + j], e.connectivity[i + (j + 1) % k])];
    }
    if (e.dim == 1 && e.type == ElementType::Line2) curves.push_back(&e);
  }
  std::sort(curves.begin(), curves.end(), [](const EntityMesh* a, const EntityMesh* b) { return a->tag < b->tag; });
  std::vector<BoundaryEdge> out;
  std::set<Edge> seen;
  for (const EntityMesh* c : curves) {
    const int group =
        c->physical_tags.empty() ? 0 : *std::min_element(c->physical_tags.begin(), c->physical_tags.end());
    for (std::size_t i = 0; i + 2 <= c->connectivity.size(); i += 2) {
      const std::uint32_t a = c->connectivity[i], b = c->connectivity[i + 1];
      const auto it = faces_on.find(key(a, b));
      if (it == faces_on.end() || it->second != 1 || !seen.insert(key(a, b)).second) continue;
      out.push_back({a, b, c->tag, group});
    }
  }
  return out;
}

}  // namespace sm::io
