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

std::vector<std::size_t> dim_tag_order(const MeshModel& m) {
  std::vector<std::size_t> order(m.entities.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const EntityMesh &ea = m.entities[a], &eb = m.entities[b];
    return std::tie(ea.dim, ea.tag) < std::tie(eb.dim, eb.tag);
  });
  return order;
}

// The partitioned entities' nodes: each used node goes to the first of them, in (dim,
// tag) order, with an element using it; the model's own entities keep only the nodes no
// element uses.
void classify_nodes(MeshModel& m) {
  std::vector<char> owned(m.xyz.size(), 0);
  for (std::size_t i : dim_tag_order(m)) {
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

}  // namespace

MeshModel partitioned_model(const MeshModel& mesh, const MeshPartition& partition) {
  MeshModel out;
  out.xyz = mesh.xyz;
  out.physicals = mesh.physicals;
  out.num_partitions = partition.parts;
  const std::vector<std::size_t> order = dim_tag_order(mesh);
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
  // Pieces: (model entity index, part) -> entity index in `out`.
  std::map<std::pair<std::size_t, int>, std::size_t> piece_of;
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
      piece_of[{i, p}] = out.entities.size();
      out.entities.push_back(std::move(piece));
    }
  }
  // Interfaces: the sides of 2D elements in different parts.
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
  struct Interface {
    std::vector<std::uint32_t> lines;
    std::set<std::pair<std::size_t, int>> sides;   // (piece index in out, sign)
  };
  std::map<std::tuple<int, int, int>, Interface> interfaces;   // (parent surface tag, p, q)
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i == 2 && sides[i].part != sides[i + 1].part) {
      const Side& ref = sides[i].part < sides[i + 1].part ? sides[i] : sides[i + 1];
      const Side& other = &ref == &sides[i] ? sides[i + 1] : sides[i];
      Interface& f = interfaces[{mesh.entities[ref.entity].tag, ref.part, other.part}];
      f.lines.push_back(ref.a), f.lines.push_back(ref.b);
      f.sides.insert({piece_of.at({ref.entity, ref.part}), 1});
      f.sides.insert({piece_of.at({other.entity, other.part}), -1});
    }
    i = j;
  }
  for (auto& [key, f] : interfaces) {
    EntityMesh c;
    c.dim = 1;
    c.tag = next_tag[1]++;
    c.type = ElementType::Line2;
    c.connectivity = std::move(f.lines);
    c.partitions = {std::get<1>(key), std::get<2>(key)};
    c.parent_dim = 2;
    c.parent_tag = std::get<0>(key);
    for (const auto& [piece, sign] : f.sides) out.entities[piece].boundary.push_back(sign * c.tag);
    out.entities.push_back(std::move(c));
  }
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
  // Boundaries: a surface piece bounded by the pieces of its curves in the same part
  // (with the model's signs) and by its interfaces (added above); curves by their ends.
  std::map<int, std::size_t> curve_index;   // model curve tag -> entity index
  for (std::size_t j = 0; j < mesh.entities.size(); ++j)
    if (mesh.entities[j].dim == 1) curve_index.emplace(mesh.entities[j].tag, j);
  for (const auto& [key, idx] : piece_of) {
    const EntityMesh& e = mesh.entities[key.first];
    EntityMesh& piece = out.entities[idx];
    if (e.dim == 2) {
      std::vector<int> bnd;
      for (int signed_tag : e.boundary) {
        const auto c = curve_index.find(std::abs(signed_tag));
        if (c == curve_index.end()) continue;
        if (const auto it = piece_of.find({c->second, key.second}); it != piece_of.end())
          bnd.push_back(signed_tag < 0 ? -out.entities[it->second].tag : out.entities[it->second].tag);
      }
      bnd.insert(bnd.end(), piece.boundary.begin(), piece.boundary.end());
      piece.boundary = std::move(bnd);
    }
  }
  for (EntityMesh& e : out.entities)
    if (!e.partitions.empty() && e.dim == 1) e.boundary = curve_ends(e, point_at);
  classify_nodes(out);
  return out;
}

MeshModel partition_piece(const MeshModel& partitioned, int part) {
  MeshModel out;
  out.xyz = partitioned.xyz;
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
