// Dual graph of the 2D elements: every element side is keyed by its two node ids (the
// smaller first), sorted, and equal keys make a graph edge. Sorting rather than hashing
// keeps the graph, hence METIS's answer, independent of any hash seed.
#include "io/dual_graph.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace sm::io {

DualGraph dual_graph_2d(const MeshModel& mesh) {
  const std::vector<std::size_t> order = entity_order(mesh);
  DualGraph g;
  struct Side {
    std::uint32_t lo, hi, element;
  };
  std::vector<Side> sides;
  for (std::size_t i : order) {
    const EntityMesh& e = mesh.entities[i];
    if (e.dim != 2) continue;
    const int npe = nodes_per_element(e.type);
    const std::size_t ne = e.connectivity.size() / npe;
    for (std::size_t k = 0; k < ne; ++k) {
      const auto id = static_cast<std::uint32_t>(g.elements.size());
      g.elements.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k));
      const std::uint32_t* c = &e.connectivity[k * npe];
      for (int j = 0; j < npe; ++j) {
        const std::uint32_t a = c[j], b = c[(j + 1) % npe];
        sides.push_back({std::min(a, b), std::max(a, b), id});
      }
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return std::tie(a.lo, a.hi, a.element) < std::tie(b.lo, b.hi, b.element);
  });
  // Each run of equal sides links every pair in it (two elements in a conforming mesh).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = a + 1; b < j; ++b)
        if (sides[a].element != sides[b].element) {
          links.emplace_back(sides[a].element, sides[b].element);
          links.emplace_back(sides[b].element, sides[a].element);
        }
    i = j;
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  g.xadj.assign(g.elements.size() + 1, 0);
  for (const auto& [a, b] : links) ++g.xadj[a + 1];
  for (std::size_t i = 0; i < g.elements.size(); ++i) g.xadj[i + 1] += g.xadj[i];
  g.adjncy.reserve(links.size());
  for (const auto& [a, b] : links) g.adjncy.push_back(static_cast<std::int32_t>(b));
  return g;
}

}  // namespace sm::io
