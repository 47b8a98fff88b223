// Building the partitioned entities (see partitioned_model.h). Everything is keyed by
// sorted vectors and std::map, so that the tags and the node order depend only on the
// mesh and the partition.
#include "io/partitioned_model.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace sm::io {
namespace {

// The partitioned entities' nodes: each used node goes to the first of them, in (dim,
// tag) order, with an element using it; the model's own entities keep only the nodes no
// element uses.
void classify_nodes(MeshModel& m) {
  std::vector<char> owned(m.xyz.size(), 0);
  for (std::size_t i : entity_order(m)) {
    EntityMesh& e = m.entities[i];
    if (e.partitions.empty()) continue;
    e.nodes.clear();
    e.params.clear();
    for (std::uint32_t n : e.connectivity)
      if (!owned[n]) owned[n] = 1, e.nodes.push_back(n);
  }
  for (EntityMesh& e : m.entities) {
    if (!e.partitions.empty()) continue;
    std::vector<std::uint32_t> keep;
    std::vector<double> params;
    const std::size_t d = e.nodes.empty() ? 0 : e.params.size() / e.nodes.size();
    for (std::size_t k = 0; k < e.nodes.size(); ++k) {
      if (owned[e.nodes[k]]) continue;
      keep.push_back(e.nodes[k]);
      for (std::size_t j = 0; j < d; ++j) params.push_back(e.params[k * d + j]);
    }
    e.nodes = std::move(keep);
    e.params = std::move(params);
  }
}

// A curve's bounding points: the ends of its chains of lines that are point entities,
// + where a chain starts and - where it ends (Gmsh's begin/end convention).
std::vector<int> curve_ends(const EntityMesh& c, const std::map<std::uint32_t, int>& point_at) {
  std::map<std::uint32_t, int> degree, starts;
  for (std::size_t k = 0; k + 1 < c.connectivity.size(); k += 2) {
    ++degree[c.connectivity[k]], ++degree[c.connectivity[k + 1]];
    ++starts[c.connectivity[k]];
  }
  std::vector<int> out;
  for (const auto& [n, d] : degree) {
    if (d % 2 == 0) continue;
    const auto it = point_at.find(n);
    if (it == point_at.end()) continue;
    out.push_back(starts.count(n) ? it->second : -it->second);
  }
  std::stable_sort(out.begin(), out.end(), [](int a, int b) { return (a < 0) < (b < 0); });
  return out;
}

// Connected pieces of an entity's elements: 2D elements joined by a shared side, lines
// by a shared node (union-find over sorted keys); the piece of each element, numbered in
// the order of their first element, and the count in *count.
std::vector<std::uint32_t> connected_pieces(const EntityMesh& e, std::uint32_t* count) {
  const int npe = nodes_per_element(e.type);
  const std::size_t ne = e.connectivity.size() / npe;
  std::vector<std::uint32_t> root(ne);
  std::iota(root.begin(), root.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> keys;   // (lo, hi, element)
  for (std::size_t k = 0; k < ne; ++k) {
    const std::uint32_t* c = &e.connectivity[k * npe];
    const auto el = static_cast<std::uint32_t>(k);
    if (e.dim == 2) {
      for (int j = 0; j < npe; ++j)
        keys.emplace_back(std::min(c[j], c[(j + 1) % npe]), std::max(c[j], c[(j + 1) % npe]), el);
    } else {
      for (int j = 0; j < npe; ++j) keys.emplace_back(c[j], 0u, el);
    }
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (std::get<0>(keys[i]) == std::get<0>(keys[i - 1]) && std::get<1>(keys[i]) == std::get<1>(keys[i - 1])) {
      const std::uint32_t a = find(std::get<2>(keys[i])), b = find(std::get<2>(keys[i - 1]));
      if (a != b) root[std::max(a, b)] = std::min(a, b);
    }
  std::vector<std::uint32_t> piece(ne), number(ne, UINT32_MAX);
  std::uint32_t n = 0;
  for (std::size_t k = 0; k < ne; ++k) {
    const std::uint32_t r = find(static_cast<std::uint32_t>(k));
    if (number[r] == UINT32_MAX) number[r] = n++;
    piece[k] = number[r];
  }
  *count = n;
  return piece;
}

// Each partitioned entity of `dim` whose elements are not connected becomes one entity per
// connected piece, each with a new tag (as Gmsh 4.8.4's divideNonConnectedEntities); the
// first piece takes the entity's place in the list.
void divide_disconnected(MeshModel& m, int dim, int& next_tag) {
  const std::size_t n = m.entities.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (m.entities[i].partitions.empty() || m.entities[i].dim != dim) continue;
    std::uint32_t count = 0;
    const std::vector<std::uint32_t> piece = connected_pieces(m.entities[i], &count);
    if (count < 2) continue;
    EntityMesh whole = std::move(m.entities[i]);
    const int npe = nodes_per_element(whole.type);
    std::vector<EntityMesh> parts(count);
    for (EntityMesh& p : parts) {
      p.dim = whole.dim;
      p.tag = next_tag++;
      p.type = whole.type;
      p.physical_tags = whole.physical_tags;
      p.partitions = whole.partitions;
      p.parent_dim = whole.parent_dim;
      p.parent_tag = whole.parent_tag;
    }
    for (std::size_t k = 0; k < piece.size(); ++k)
      parts[piece[k]].connectivity.insert(parts[piece[k]].connectivity.end(), &whole.connectivity[k * npe],
                                          &whole.connectivity[k * npe] + npe);
    m.entities[i] = std::move(parts[0]);
    for (std::uint32_t k = 1; k < count; ++k) m.entities.push_back(std::move(parts[k]));
  }
}

// The partitioned entities' boundaries: a surface's are the partitioned curves with a line
// on a side of its elements, + where the line runs as the element's side and - against it,
// in tag order; a curve's are its chain ends (curve_ends).
void set_boundaries(MeshModel& m, const std::map<std::uint32_t, int>& point_at) {
  struct SideOf {
    std::uint32_t lo, hi, a;
    std::size_t surface;
  };
  std::vector<SideOf> sides;
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    const EntityMesh& e = m.entities[i];
    if (e.partitions.empty() || e.dim != 2) continue;
    const int npe = nodes_per_element(e.type);
    for (std::size_t k = 0; k + npe <= e.connectivity.size(); k += npe)
      for (int j = 0; j < npe; ++j) {
        const std::uint32_t a = e.connectivity[k + j], b = e.connectivity[k + (j + 1) % npe];
        sides.push_back({std::min(a, b), std::max(a, b), a, i});
      }
  }
  const auto less = [](const SideOf& x, const SideOf& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); };
  std::stable_sort(sides.begin(), sides.end(), less);
  std::map<std::size_t, std::map<int, int>> bounded_by;   // surface index -> curve tag -> sign
  for (EntityMesh& c : m.entities) {
    if (c.partitions.empty() || c.dim != 1) continue;
    for (std::size_t k = 0; k + 1 < c.connectivity.size(); k += 2) {
      const std::uint32_t a = c.connectivity[k], b = c.connectivity[k + 1];
      const SideOf key{std::min(a, b), std::max(a, b), 0, 0};
      for (auto it = std::lower_bound(sides.begin(), sides.end(), key, less);
           it != sides.end() && it->lo == key.lo && it->hi == key.hi; ++it)
        bounded_by[it->surface].emplace(c.tag, it->a == a ? 1 : -1);
    }
    c.boundary = curve_ends(c, point_at);
  }
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    EntityMesh& e = m.entities[i];
    if (e.partitions.empty() || e.dim != 2) continue;
    e.boundary.clear();
    for (const auto& [tag, sign] : bounded_by[i]) e.boundary.push_back(sign * tag);
  }
}

}  // namespace

MeshModel partitioned_model(const MeshModel& mesh, const MeshPartition& partition, bool topology) {
  MeshModel out;
  out.xyz = mesh.xyz;
  out.physicals = mesh.physicals;
  out.num_partitions = partition.parts;
  const std::vector<std::size_t> order = entity_order(mesh);
  int next_tag[4] = {1, 1, 1, 1};
  for (const EntityMesh& e : mesh.entities) {
    const int d = std::clamp(e.dim, 0, 3);
    next_tag[d] = std::max(next_tag[d], e.tag + 1);
  }
  for (const EntityMesh& e : mesh.entities) {
    EntityMesh copy = e;
    copy.connectivity.clear();
    out.entities.push_back(std::move(copy));
  }
  // Pieces: each model entity's elements of each part.
  for (std::size_t i : order) {
    const EntityMesh& e = mesh.entities[i];
    const int npe = nodes_per_element(e.type);
    const std::vector<int>& parts = partition.element_part[i];
    for (int p = 1; p <= partition.parts; ++p) {
      EntityMesh piece;
      for (std::size_t k = 0; k < parts.size(); ++k)
        if (parts[k] == p) piece.connectivity.insert(piece.connectivity.end(), &e.connectivity[k * npe],
                                                     &e.connectivity[k * npe] + npe);
      if (piece.connectivity.empty()) continue;
      piece.dim = e.dim;
      piece.tag = next_tag[std::clamp(e.dim, 0, 3)]++;
      piece.type = e.type;
      piece.physical_tags = e.physical_tags;
      piece.partitions = {p};
      piece.parent_dim = e.dim;
      piece.parent_tag = e.tag;
      out.entities.push_back(std::move(piece));
    }
  }
  for (int d = 2; d >= 0; --d) divide_disconnected(out, d, next_tag[d]);
  if (!topology) {
    set_boundaries(out, {});
    classify_nodes(out);
    return out;
  }
  // Interfaces: the sides of 2D elements in different parts, oriented as the side of the
  // lower part's element.
  struct Side {
    std::uint32_t lo, hi, a, b;
    std::size_t entity;
    int part;
  };
  std::vector<Side> sides;
  for (std::size_t i : order) {
    const EntityMesh& e = mesh.entities[i];
    if (e.dim != 2) continue;
    const int npe = nodes_per_element(e.type);
    for (std::size_t k = 0; k < partition.element_part[i].size(); ++k) {
      const std::uint32_t* c = &e.connectivity[k * npe];
      for (int j = 0; j < npe; ++j) {
        const std::uint32_t a = c[j], b = c[(j + 1) % npe];
        sides.push_back({std::min(a, b), std::max(a, b), a, b, i, partition.element_part[i][k]});
      }
    }
  }
  std::stable_sort(sides.begin(), sides.end(),
                   [](const Side& x, const Side& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); });
  std::map<std::tuple<int, int, int>, std::vector<std::uint32_t>> interfaces;   // (parent surface tag, p, q)
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i == 2 && sides[i].part != sides[i + 1].part) {
      const Side& ref = sides[i].part < sides[i + 1].part ? sides[i] : sides[i + 1];
      const Side& other = &ref == &sides[i] ? sides[i + 1] : sides[i];
      std::vector<std::uint32_t>& lines = interfaces[{mesh.entities[ref.entity].tag, ref.part, other.part}];
      lines.push_back(ref.a), lines.push_back(ref.b);
    }
    i = j;
  }
  for (auto& [key, lines] : interfaces) {
    EntityMesh c;
    c.dim = 1;
    c.tag = next_tag[1]++;
    c.type = ElementType::Line2;
    c.connectivity = std::move(lines);
    c.partitions = {std::get<1>(key), std::get<2>(key)};
    c.parent_dim = 2;
    c.parent_tag = std::get<0>(key);
    out.entities.push_back(std::move(c));
  }
  divide_disconnected(out, 1, next_tag[1]);
  // Partition points: nodes on curves of different partitioned entities whose parts differ.
  std::map<std::uint32_t, std::vector<std::size_t>> curves_at;
  std::map<std::uint32_t, int> point_at;   // node -> tag of the point entity on it
  for (std::size_t i = 0; i < out.entities.size(); ++i) {
    const EntityMesh& e = out.entities[i];
    if (e.partitions.empty()) continue;
    if (e.dim == 0)
      for (std::uint32_t n : e.connectivity) point_at.emplace(n, e.tag);
    if (e.dim == 1)
      for (std::uint32_t n : e.connectivity) {
        std::vector<std::size_t>& at = curves_at[n];
        if (at.empty() || at.back() != i) at.push_back(i);
      }
  }
  for (const auto& [n, curves] : curves_at) {
    if (curves.size() < 2 || point_at.count(n)) continue;
    std::set<int> parts;
    for (std::size_t c : curves) parts.insert(out.entities[c].partitions.begin(), out.entities[c].partitions.end());
    if (parts.size() < 2) continue;
    EntityMesh pt;
    pt.dim = 0;
    pt.tag = next_tag[0]++;
    pt.type = ElementType::Point1;
    pt.connectivity = {n};
    pt.partitions.assign(parts.begin(), parts.end());
    pt.parent_dim = out.entities[curves.front()].parent_dim;
    pt.parent_tag = out.entities[curves.front()].parent_tag;
    point_at[n] = pt.tag;
    out.entities.push_back(std::move(pt));
  }
  set_boundaries(out, point_at);
  classify_nodes(out);
  return out;
}

MeshModel partition_piece(const MeshModel& partitioned, int part) {
  return partition_piece(partitioned, part, partitioned.xyz);
}

MeshModel partition_piece(const MeshModel& partitioned, int part, std::vector<Vec3> xyz) {
  MeshModel out;
  out.xyz = std::move(xyz);
  out.physicals = partitioned.physicals;
  out.num_partitions = partitioned.num_partitions;
  std::set<std::pair<int, int>> present;
  for (const EntityMesh& e : partitioned.entities) {
    if (e.partitions.empty()) {
      // Gmsh adds the model's entities to every part's model, without mesh.
      EntityMesh model_entity = e;
      model_entity.nodes.clear();
      model_entity.params.clear();
      out.entities.push_back(std::move(model_entity));
    } else if (std::find(e.partitions.begin(), e.partitions.end(), part) != e.partitions.end()) {
      out.entities.push_back(e);
      present.insert({e.dim, e.tag});
    }
  }
  for (EntityMesh& e : out.entities) {
    if (e.partitions.empty()) continue;
    std::vector<int> bnd;
    for (int t : e.boundary)
      if (present.count({e.dim - 1, std::abs(t)})) bnd.push_back(t);
    e.boundary = std::move(bnd);
  }
  classify_nodes(out);
  return out;
}

}  // namespace sm::io
