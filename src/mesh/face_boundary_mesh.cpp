// Steps 3 and 4 of a face: Delaunay of the boundary nodes, edge recovery, hole removal,
// then the face's sizing (face_boundary_mesh.h).
#include "mesh/face_boundary_mesh.h"

#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mesh/cdt.h"
#include "mesh/delaunay.h"
#include "mesh/face_sizing.h"

namespace sm {
namespace {

// The local vertex of global node `node`, made (its plane point added) on first use.
std::uint32_t local(FaceWork& f, std::uint32_t node) {
  if (f.local_of[node] == kNoLocal) {
    f.local_of[node] = static_cast<std::uint32_t>(f.global.size());
    f.global.push_back(node);
    f.tri.add_vertex(f.plane.node_plane(f.mesh.nodes[node]));
  }
  return f.local_of[node];
}

}  // namespace

bool triangulate_boundary(FaceWork& f) {
  // The scratch map is shared by all faces and reset entry by entry (O(face) per face).
  f.local_of.resize(f.mesh.nodes.size(), kNoLocal);
  std::vector<Loop> loops;
  for (std::size_t ci = 0; ci < f.chains.size(); ++ci) {
    Loop L;
    L.hole = ci > 0;
    for (std::uint32_t node : f.chains[ci].nodes) L.v.push_back(VertexId{local(f, node)});
    for (std::size_t k = 0; k < L.v.size(); ++k) {
      f.edges.push_back({L.v[k], L.v[(k + 1) % L.v.size()]});
      f.edge_curve.push_back(f.chains[ci].edge_curve[k]);
    }
    loops.push_back(std::move(L));
  }
  for (const FaceChain& ch : f.emb_curves)
    for (std::size_t k = 0; k + 1 < ch.nodes.size(); ++k) {
      f.edges.push_back({VertexId{local(f, ch.nodes[k])}, VertexId{local(f, ch.nodes[k + 1])}});
      f.edge_curve.push_back(ch.edge_curve[k]);
    }
  for (std::uint32_t node : f.emb_points) local(f, node);
  f.fixed_count = f.tri.num_vertices();

  const DelaunayResult dr = delaunay(f.tri);
  if (!dr.ok()) return f.fail_because(MeshProblem::DelaunayFailed, dr.error);
  if (!dr.duplicates.empty()) {
    const std::uint32_t a = f.global[dr.duplicates[0].dup.value], b = f.global[dr.duplicates[0].kept.value];
    return f.fail(MeshProblem::BoundaryNodesCoincide, {a, b}, f.mesh.nodes[a].xyz);
  }
  const PlanarGeometry g{&f.tri.xy};
  const RecoverResult rr = recover_edges(f.tri, g, f.edges);
  if (!rr.ok()) return f.fail_because(MeshProblem::RecoveryFailed, rr.error);
  if (!rr.crossings.empty()) {
    const EdgeCrossing& x = rr.crossings[0];
    const Edge e = f.edges[x.edge];
    const int other = x.other != kNoEdge ? f.edge_curve[x.other] : 0;
    return f.fail(MeshProblem::BoundaryEdgesCross, {f.edge_curve[x.edge], other},
                  f.mesh.nodes[f.global[e.first.value]].xyz, {f.edge_curve[x.edge], other});
  }
  if (!rr.touching.empty()) {
    const VertexOnEdge& x = rr.touching[0];
    return f.fail(MeshProblem::BoundaryNodeOnEdge, {f.edge_curve[x.edge]}, f.mesh.nodes[f.global[x.v.value]].xyz,
                  {f.edge_curve[x.edge]});
  }
  // The sizes extended from the boundary are interpolated in the whole recovered
  // triangulation, holes and the hull outside the face included: a walk in it always
  // reaches the point, where one in the face alone stops at a hole and would give the
  // hole's sizes to everything behind it.
  if (f.opt.size.extend_from_boundary != 0) f.hull = f.tri;
  const DomainResult dom = remove_outside(f.tri, g, loops);
  if (!dom.ok()) return f.fail_because(MeshProblem::HoleRemovalFailed, dom.error);
  return true;
}

void make_sizing(FaceWork& f) {
  FaceSizing& sz = *f.sizing;
  sz.tag = f.tag;
  sz.bbox = f.bbox;
  sz.size = f.opt.size;
  sz.background = f.opt.background;
  sz.plane = f.plane;
  set_boundary_sizes(sz, std::move(f.hull), f.fixed_count, f.edges, f.global, f.mesh, f.model, f.estimate_only);
  f.hull = TriangleStore{};
}

}  // namespace sm
