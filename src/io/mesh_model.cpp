// Small helpers of the writer-facing mesh description.
#include "io/mesh_model.h"

#include <algorithm>
#include <numeric>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "base/check.h"

namespace sm::io {

constexpr std::uint32_t kNoOwner = 0xFFFFFFFFu;

int nodes_per_element(ElementType type) {
  switch (type) {
    case ElementType::Point1: return 1;
    case ElementType::Line2: return 2;
    case ElementType::Triangle3: return 3;
    case ElementType::Quad4: return 4;
  }
  SM_ASSERT(false, "unknown element type");
  return 0;
}

std::size_t MeshModel::element_count() const {
  std::size_t n = 0;
  for (const EntityMesh& e : entities) n += e.connectivity.size() / nodes_per_element(e.type);
  return n;
}

std::string validate_mesh_model(const MeshModel& m) {
  if (m.xyz.size() >= kNoOwner) return "too many nodes for 32-bit node indices";
  std::vector<std::uint32_t> owner(m.xyz.size(), kNoOwner);
  // Sorted (dim, tag) pairs: a world 1D mesh has ~10^5 point entities.
  std::vector<std::tuple<int, int, int, std::size_t>> keys;   // dim, tag, type, index
  keys.reserve(m.entities.size());
  for (std::size_t i = 0; i < m.entities.size(); ++i)
    keys.emplace_back(m.entities[i].dim, m.entities[i].tag, static_cast<int>(m.entities[i].type), i);
  std::sort(keys.begin(), keys.end());
  for (std::size_t k = 1; k < keys.size(); ++k) {
    const auto& [d0, t0, y0, i0] = keys[k - 1];
    const auto& [d1, t1, y1, i1] = keys[k];
    if (d0 != d1 || t0 != t1) continue;
    if (y0 == y1) return fmt::format("entity (dim {}, tag {}) listed twice", d1, t1);
    if (!m.entities[i1].nodes.empty())
      return fmt::format("entity (dim {}, tag {}): its second element block owns nodes", d1, t1);
  }
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    const EntityMesh& e = m.entities[i];
    // Point 0 is valid: Gmsh takes it in scripts and reads it back from MSH files.
    if (e.dim < 0 || e.dim > 3 || e.tag < 0 || (e.tag == 0 && e.dim != 0))
      return fmt::format("invalid entity (dim {}, tag {})", e.dim, e.tag);
    for (std::uint32_t n : e.nodes) {
      if (n >= m.xyz.size()) return fmt::format("entity ({}, {}) owns node {} out of range", e.dim, e.tag, n);
      if (owner[n] != kNoOwner)
        return fmt::format("node {} is owned by two entities ({}, {}) and ({}, {})", n,
                           m.entities[owner[n]].dim, m.entities[owner[n]].tag, e.dim, e.tag);
      owner[n] = static_cast<std::uint32_t>(i);
    }
    if (e.connectivity.size() % nodes_per_element(e.type) != 0)
      return fmt::format("entity ({}, {}) has a truncated element", e.dim, e.tag);
  }
  for (const EntityMesh& e : m.entities)
    for (std::uint32_t n : e.connectivity) {
      if (n >= m.xyz.size())
        return fmt::format("element of entity ({}, {}) uses node {} out of range", e.dim, e.tag, n);
      if (owner[n] == kNoOwner) return fmt::format("node {} is used by an element but owned by no entity", n);
    }
  return {};
}

std::vector<std::size_t> entity_order(const MeshModel& m) {
  std::vector<std::size_t> order(m.entities.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const EntityMesh &ea = m.entities[a], &eb = m.entities[b];
    if (ea.dim != eb.dim) return ea.dim < eb.dim;
    return ea.tag != eb.tag ? ea.tag < eb.tag : static_cast<int>(ea.type) < static_cast<int>(eb.type);
  });
  return order;
}

bool is_extra_block(const MeshModel& m, const std::vector<std::size_t>& order, std::size_t k) {
  if (k == 0) return false;
  const EntityMesh &a = m.entities[order[k - 1]], &b = m.entities[order[k]];
  return a.dim == b.dim && a.tag == b.tag && a.partitions == b.partitions && a.parent_tag == b.parent_tag;
}

}  // namespace sm::io
