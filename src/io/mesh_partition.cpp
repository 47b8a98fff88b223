// METIS on the dual graph, then the lower-dimensional elements placed as Gmsh 4.8.4's
// partitionGraph corrects them: a line takes the part of a 2D element it is a side of,
// a point element the part of a line (or else a 2D element) through its node.
#include "io/mesh_partition.h"

#include <metis.h>

#include <algorithm>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "io/dual_graph.h"

namespace sm::io {
namespace {

// METIS's own random choices start from this seed, so a run is reproducible.
constexpr idx_t kMetisSeed = 1;

struct SideKey {
  std::uint32_t lo, hi;
  int part;
};

}  // namespace

MeshPartition aligned_partition(const MeshPartition& partition, const MeshModel& mesh) {
  MeshPartition out = partition;
  std::map<std::pair<int, int>, std::size_t> row;
  for (std::size_t i = 0; i < partition.entities.size(); ++i) row.emplace(partition.entities[i], i);
  out.element_part.clear();
  out.entities.clear();
  for (const EntityMesh& e : mesh.entities) {
    const std::size_t n = e.connectivity.size() / nodes_per_element(e.type);
    const auto it = row.find({e.dim, e.tag});
    std::vector<int> parts = it != row.end() ? partition.element_part[it->second] : std::vector<int>{};
    parts.resize(n, 1);
    out.element_part.push_back(std::move(parts));
    out.entities.emplace_back(e.dim, e.tag);
  }
  return out;
}

bool partition_mesh(const MeshModel& mesh, const MeshPartitionOptions& opt, MeshPartition* out, PartitionError* error) {
  const DualGraph g = dual_graph_2d(mesh);
  if (g.size() == 0) {
    *error = {PartitionProblem::NoElements, 0};
    return false;
  }
  if (opt.parts < 1 || static_cast<std::size_t>(opt.parts) > g.size()) {
    *error = {PartitionProblem::PartCount, g.size()};
    return false;
  }
  std::vector<idx_t> part(g.size(), 0);
  idx_t objval = 0;
  if (opt.parts > 1) {
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_PTYPE] = opt.algorithm == 2 ? METIS_PTYPE_KWAY : METIS_PTYPE_RB;
    if (opt.ufactor >= 0) options[METIS_OPTION_UFACTOR] = opt.ufactor;
    options[METIS_OPTION_SEED] = kMetisSeed;
    options[METIS_OPTION_NUMBERING] = 0;
    idx_t n = static_cast<idx_t>(g.size()), ncon = 1, nparts = opt.parts;
    std::vector<idx_t> xadj(g.xadj.begin(), g.xadj.end()), adjncy(g.adjncy.begin(), g.adjncy.end());
    if (adjncy.empty()) adjncy.push_back(0);   // METIS reads adjncy[0] even with no edge
    const int rc = opt.algorithm == 2
                       ? METIS_PartGraphKway(&n, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr, nullptr, &nparts,
                                             nullptr, nullptr, options, &objval, part.data())
                       : METIS_PartGraphRecursive(&n, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr, nullptr,
                                                  &nparts, nullptr, nullptr, options, &objval, part.data());
    if (rc != METIS_OK) {
      error->problem = rc == METIS_ERROR_MEMORY ? PartitionProblem::MetisOutOfMemory : PartitionProblem::MetisFailed;
      return false;
    }
  }
  MeshPartition& r = *out;
  r = MeshPartition{};
  r.parts = opt.parts;
  r.element_part.resize(mesh.entities.size());
  for (std::size_t i = 0; i < mesh.entities.size(); ++i) {
    const EntityMesh& e = mesh.entities[i];
    r.element_part[i].assign(e.connectivity.size() / nodes_per_element(e.type), 0);
    r.entities.emplace_back(e.dim, e.tag);
  }
  r.part_elements.assign(opt.parts, 0);
  for (std::size_t v = 0; v < g.size(); ++v) {
    const int p = static_cast<int>(part[v]) + 1;
    r.element_part[g.elements[v].first][g.elements[v].second] = p;
    ++r.part_elements[p - 1];
  }
  // The cut counted here rather than taken from METIS's objval, which recursive
  // bisection reports for its last level only.
  for (std::size_t v = 0; v < g.size(); ++v)
    for (std::int32_t k = g.xadj[v]; k < g.xadj[v + 1]; ++k)
      if (static_cast<std::size_t>(g.adjncy[k]) > v && part[v] != part[g.adjncy[k]]) ++r.edge_cut;
  const std::uint64_t largest = *std::max_element(r.part_elements.begin(), r.part_elements.end());
  r.imbalance = static_cast<double>(largest) * opt.parts / static_cast<double>(g.size());

  // Sides of the 2D elements with the part of the first element (graph order) having them.
  std::vector<SideKey> sides;
  std::vector<int> node_of_2d(mesh.xyz.size(), 0);
  for (std::size_t v = 0; v < g.size(); ++v) {
    const auto [ei, k] = g.elements[v];
    const EntityMesh& e = mesh.entities[ei];
    const int npe = nodes_per_element(e.type);
    const std::uint32_t* c = &e.connectivity[std::size_t{k} * npe];
    const int p = static_cast<int>(part[v]) + 1;
    for (int j = 0; j < npe; ++j) {
      const std::uint32_t a = c[j], b = c[(j + 1) % npe];
      sides.push_back({std::min(a, b), std::max(a, b), p});
      if (!node_of_2d[a]) node_of_2d[a] = p;
    }
  }
  std::stable_sort(sides.begin(), sides.end(),
                   [](const SideKey& a, const SideKey& b) { return std::tie(a.lo, a.hi) < std::tie(b.lo, b.hi); });
  auto side_part = [&](std::uint32_t a, std::uint32_t b) {
    const SideKey key{std::min(a, b), std::max(a, b), 0};
    const auto it = std::lower_bound(sides.begin(), sides.end(), key, [](const SideKey& x, const SideKey& y) {
      return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
    });
    return it != sides.end() && it->lo == key.lo && it->hi == key.hi ? it->part : 0;
  };
  std::vector<int> node_of_line(mesh.xyz.size(), 0);
  for (std::size_t i = 0; i < mesh.entities.size(); ++i) {
    const EntityMesh& e = mesh.entities[i];
    if (e.dim != 1) continue;
    for (std::size_t k = 0; k < r.element_part[i].size(); ++k) {
      const std::uint32_t a = e.connectivity[2 * k], b = e.connectivity[2 * k + 1];
      int p = side_part(a, b);
      if (!p) p = node_of_2d[a] ? node_of_2d[a] : (node_of_2d[b] ? node_of_2d[b] : 1);
      r.element_part[i][k] = p;
      if (!node_of_line[a]) node_of_line[a] = p;
      if (!node_of_line[b]) node_of_line[b] = p;
    }
  }
  for (std::size_t i = 0; i < mesh.entities.size(); ++i) {
    const EntityMesh& e = mesh.entities[i];
    if (e.dim != 0) continue;
    for (std::size_t k = 0; k < r.element_part[i].size(); ++k) {
      const std::uint32_t a = e.connectivity[k];
      r.element_part[i][k] = node_of_line[a] ? node_of_line[a] : (node_of_2d[a] ? node_of_2d[a] : 1);
    }
  }
  r.node_part.assign(mesh.xyz.size(), 0);
  for (std::size_t i = 0; i < mesh.entities.size(); ++i) {
    const EntityMesh& e = mesh.entities[i];
    const int npe = nodes_per_element(e.type);
    for (std::size_t k = 0; k < r.element_part[i].size(); ++k)
      for (int j = 0; j < npe; ++j) {
        int& np = r.node_part[e.connectivity[k * npe + j]];
        const int p = r.element_part[i][k];
        if (np == 0 || p < np) np = p;
      }
  }
  return true;
}

}  // namespace sm::io
