// ModelMesh -> MeshModel: classification, boundaries and physical groups as Gmsh writes
// them (docs/gmsh-compatibility.md).
#include "io/from_model_mesh.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

#include "base/parallel.h"

namespace sm::io {

namespace {

constexpr std::uint32_t kDropped = 0xFFFFFFFFu;
constexpr std::size_t kChunk = std::size_t{1} << 16;

// flag[v] = 1 for every node v of `nodes`, on `threads` threads: each store is the same
// value, made atomic (relaxed) where two elements share a node.
void mark_all(std::vector<char>& flag, const std::vector<std::uint32_t>& nodes, int threads) {
  parallel_for_chunks(threads, nodes.size(), kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) std::atomic_ref<char>(flag[nodes[k]]).store(1, std::memory_order_relaxed);
  });
}

// v = index[v] for every v of `nodes`, on `threads` threads.
void renumber(std::vector<std::uint32_t>& nodes, const std::vector<std::uint32_t>& index, int threads) {
  parallel_for_chunks(threads, nodes.size(), kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) nodes[k] = index[nodes[k]];
  });
}

// Leaves out what the 2D mesher left out, and numbers the nodes as the MSH writer does.
// Curves of a meshed surface's loops whose nodes no 2D element uses (the closed curves of
// islands smaller than the mesh size: mesh2d drops their hole loops with a warning), and
// the points that no kept curve or face uses, are removed; then the nodes are
// renumbered 0.. in entity order ((dim, tag), each entity's own nodes in order), keeping
// only the nodes some kept entity owns. Returns old node -> new node (kDropped: gone).
std::vector<std::uint32_t> keep_mesh_only(const geo::Model& model, const std::vector<MeshNode>& nodes,
                                          MeshModel& out, int threads) {
  std::vector<char> in_2d(nodes.size(), 0);
  std::set<int> meshed_surfaces;
  for (const EntityMesh& e : out.entities)
    if (e.dim == 2 && !e.connectivity.empty()) {
      meshed_surfaces.insert(e.tag);
      mark_all(in_2d, e.connectivity, threads);
    }
  std::set<int> bounding;   // curves in the loops of the surfaces that have elements
  for (int tag : meshed_surfaces)
    if (const auto it = model.surfaces().find(tag); it != model.surfaces().end())
      for (int l : it->second.loops)
        if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
          for (int c : loop->curves) bounding.insert(std::abs(c));
  std::vector<char> dropped_entity(out.entities.size(), 0);
  std::vector<char> on_dropped(nodes.size(), 0);
  for (std::size_t i = 0; i < out.entities.size(); ++i) {
    const EntityMesh& e = out.entities[i];
    if (e.dim != 1 || e.connectivity.empty() || !bounding.count(e.tag)) continue;
    if (std::none_of(e.connectivity.begin(), e.connectivity.end(), [&](std::uint32_t v) { return in_2d[v] != 0; })) {
      dropped_entity[i] = 1;
      for (std::uint32_t v : e.connectivity) on_dropped[v] = 1;
    }
  }
  // A point no kept curve or face uses goes, once there is a 2D mesh: the ends of the
  // dropped curves, and, in a model on a sphere (a PolarSphere or Sphere geometry), the
  // construction points (the sphere's centre and pole, a circle's centre), which are no
  // part of its surface mesh, and in a model with physical groups those in none (Gmsh
  // writes only the groups' entities then). A flat model without groups keeps them, as
  // Gmsh writes every model point (a circle's centre in its benchmarks transfinite_b.geo
  // and transf_complex.geo). A point in a physical group stays (it was asked for by name,
  // as Gmsh writes it), unless it ended a dropped curve.
  std::vector<char> used_by_kept(nodes.size(), 0);
  for (std::size_t i = 0; i < out.entities.size(); ++i)
    if (!dropped_entity[i] && out.entities[i].dim > 0) mark_all(used_by_kept, out.entities[i].connectivity, threads);
  const bool drop_construction = !model.geometries().empty() || !out.physicals.empty();
  if (!meshed_surfaces.empty())
    for (std::size_t i = 0; i < out.entities.size(); ++i) {
      const EntityMesh& e = out.entities[i];
      if (e.dim != 0 || e.nodes.size() != 1 || used_by_kept[e.nodes[0]]) continue;
      if (on_dropped[e.nodes[0]] || (drop_construction && e.physical_tags.empty())) dropped_entity[i] = 1;
    }
  std::vector<EntityMesh> kept;
  kept.reserve(out.entities.size());
  for (std::size_t i = 0; i < out.entities.size(); ++i)
    if (!dropped_entity[i]) kept.push_back(std::move(out.entities[i]));
  out.entities = std::move(kept);

  // The points straight from the ModelMesh's nodes, counted first so that the array is
  // sized once: no second copy of every point beside it at the writing's peak.
  std::vector<std::uint32_t> index(nodes.size(), kDropped);
  std::size_t kept_nodes = 0;
  const std::vector<std::size_t> order = entity_order(out);
  for (std::size_t i : order)
    for (std::uint32_t v : out.entities[i].nodes)
      if (index[v] == kDropped) index[v] = static_cast<std::uint32_t>(kept_nodes++);
  out.xyz.resize(kept_nodes);
  parallel_for_chunks(threads, nodes.size(), kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      if (index[v] != kDropped) out.xyz[index[v]] = nodes[v].xyz;
  });
  for (EntityMesh& e : out.entities) {
    renumber(e.nodes, index, threads);
    renumber(e.connectivity, index, threads);   // every used node is owned (validate_mesh_model)
  }
  return index;
}

}  // namespace

MeshModel from_model_mesh(const geo::Model& model, const ModelMesh& mesh, std::vector<std::uint32_t>* node_index,
                          bool parametric, int threads) {
  threads = resolve_thread_count(threads);
  MeshModel out;   // its points are filled last, by keep_mesh_only
  // (dim, |entity tag|) -> physical tags, ascending and without repeats.
  std::map<std::pair<int, int>, std::vector<int>> groups_of;
  // A group keeps the tags of deleted entities (geo/model_edit.cpp): only the existing ones
  // count, and a group with none is not written, as Gmsh writes it.
  for (const auto& [key, g] : model.physicals()) {
    if (model.physical_entities(g.dim, g.tag).empty()) continue;
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
  // Points joined by a collapsed curve (mesh/mesh1d.cpp) share one node: the first of them
  // (smallest tag) owns it, the others keep their point element on it.
  std::vector<std::uint8_t> owned(mesh.nodes.size(), 0);
  for (const auto& [tag, node] : mesh.vertex_node) {
    EntityMesh e;
    e.dim = 0, e.tag = tag, e.type = ElementType::Point1;
    e.physical_tags = physicals(0, tag);
    if (!owned[node]) e.nodes = {node};
    owned[node] = 1;
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
      if (parametric) e.params.push_back(c.t[k]);
    }
    e.connectivity.reserve(2 * c.num_edges());
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) {
      e.connectivity.push_back(c.nodes[k]);
      e.connectivity.push_back(c.nodes[k + 1]);
    }
    out.entities.push_back(std::move(e));
  }
  // A surface's entity (its elements when meshed) with its signed boundary curves.
  auto add_surface = [&](int tag, std::vector<int> boundary) {
    EntityMesh e;
    e.dim = 2, e.tag = tag, e.type = ElementType::Triangle3;
    e.physical_tags = physicals(2, tag);
    e.boundary = std::move(boundary);
    const auto it = mesh.surfaces.find(tag);
    if (it != mesh.surfaces.end()) {
      const SurfaceMesh& sm = it->second;
      e.nodes = sm.interior_nodes;
      const bool uv = parametric && std::all_of(sm.interior_nodes.begin(), sm.interior_nodes.end(),
                                  [&](std::uint32_t n) { return mesh.nodes[n].has_uv; });
      // Sized once (grown by doubling, the last growth held the old array and one twice
      // its size at once: up to 36 bytes a triangle for 12).
      if (uv) {
        e.params.reserve(2 * sm.interior_nodes.size());
        for (std::uint32_t n : sm.interior_nodes)
          e.params.insert(e.params.end(), {mesh.nodes[n].uv.x, mesh.nodes[n].uv.y});
      }
      e.connectivity.resize(3 * sm.triangles.size());
      const auto& triangles = sm.triangles;   // a lambda may not capture a structured binding (clang 14)
      parallel_for_chunks(threads, triangles.size(), kChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t)
          std::copy(triangles[t].begin(), triangles[t].end(), e.connectivity.begin() + static_cast<std::ptrdiff_t>(3 * t));
      });
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
          return;
        }
      }
    }
    out.entities.push_back(std::move(e));
  };
  for (const auto& [tag, s] : model.surfaces()) {
    std::vector<int> boundary;
    for (int l : s.loops) {
      const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l));
      if (!loop) continue;
      if (l > 0) {
        boundary.insert(boundary.end(), loop->curves.begin(), loop->curves.end());
      } else {
        for (auto it = loop->curves.rbegin(); it != loop->curves.rend(); ++it) boundary.push_back(-*it);
      }
    }
    add_surface(tag, std::move(boundary));
  }
  // The discrete surfaces of a merged mesh (mesh/discrete_mesh.h): elements, no loops.
  for (const auto& [tag, s] : mesh.surfaces)
    if (!model.surface(tag)) add_surface(tag, {});
  std::vector<std::uint32_t> index = keep_mesh_only(model, mesh.nodes, out, threads);
  // The periodic correspondences whose entities and nodes are all kept.
  std::set<std::pair<int, int>> kept;
  for (const EntityMesh& e : out.entities) kept.insert({e.dim, e.tag});
  for (const PeriodicLink& l : mesh.periodic) {
    if (!kept.count({l.dim, l.tag}) || !kept.count({l.dim, l.master})) continue;
    PeriodicLink p{l.dim, l.tag, l.master, l.affine, {}};
    for (const auto& [a, b] : l.nodes)
      if (index[a] != kDropped && index[b] != kDropped) p.nodes.emplace_back(index[a], index[b]);
    if (p.nodes.size() == l.nodes.size()) out.periodic.push_back(std::move(p));
  }
  if (node_index) *node_index = std::move(index);
  return out;
}

}  // namespace sm::io
