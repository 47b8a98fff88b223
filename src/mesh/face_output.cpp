// Step 8 of a face: interior nodes to 3D, elements oriented (and recombined), the
// surface's mesh stored (face_output.h).
#include "mesh/face_output.h"

#include <algorithm>
#include <utility>

#include "base/parallel.h"
#include "mesh/face_sizing.h"
#include "mesh/recombine.h"

namespace sm {
namespace {

// New nodes per chunk of their placement in space: fixed, so the cut is the same for every
// thread count.
constexpr std::size_t kOutputNodeChunk = 1 << 14;

}  // namespace

void append_elements(SurfaceMesh& out, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                     const std::vector<std::array<std::uint32_t, 4>>& quads, bool flip,
                     std::span<const std::uint32_t> node) {
  out.triangles.reserve(out.triangles.size() + triangles.size());
  for (const auto& t : triangles) {
    const std::uint32_t a = node[t[0]], b = node[t[1]], c = node[t[2]];
    out.triangles.push_back(flip ? std::array<std::uint32_t, 3>{a, c, b} : std::array<std::uint32_t, 3>{a, b, c});
  }
  for (const auto& q : quads) {
    const std::uint32_t a = node[q[0]], b = node[q[1]], c = node[q[2]], d = node[q[3]];
    out.quads.push_back(flip ? std::array<std::uint32_t, 4>{a, d, c, b} : std::array<std::uint32_t, 4>{a, b, c, d});
  }
}

void store_surface(FaceWork& f, SurfaceMesh out) {
  f.res.stats.new_nodes += out.interior_nodes.size();
  f.res.stats.triangles += out.triangles.size();
  f.res.stats.quads += out.quads.size();
  ++f.res.stats.faces;
  f.mesh.surfaces[f.tag] = std::move(out);
}

void output_face(FaceWork& f) {
  SurfaceMesh sm_out;
  sm_out.tag = f.tag;
  const std::uint32_t nv = f.tri.num_vertices();
  // Local triangles, counter-clockwise in the plane; then the store's topology is freed
  // (about 32 bytes a triangle) before the nodes are made: only its points are read after.
  std::vector<std::array<std::uint32_t, 3>> local;
  local.reserve(f.tri.num_triangles());
  for (std::uint32_t t = 0; t < f.tri.num_slots(); ++t) {
    if (!f.tri.alive(TriId{t})) continue;
    local.push_back(
        {f.tri.vertex(TriId{t}, 0).value, f.tri.vertex(TriId{t}, 1).value, f.tri.vertex(TriId{t}, 2).value});
  }
  std::vector<Vec2> xy = std::move(f.tri.xy);
  f.tri = TriangleStore{};
  f.global.resize(nv, kNoLocal);  // the floor's curve nodes have theirs already
  // The node array grown once for the face: by doubling it would hold the old array and
  // one of twice its size at once (48 bytes a node). At least by half when it grows, so
  // that many small faces stay linear.
  const std::size_t need = f.mesh.nodes.size() + (nv - std::min(nv, f.fixed_count));
  if (need > f.mesh.nodes.capacity())
    f.mesh.nodes.reserve(std::max(need, f.mesh.nodes.capacity() + f.mesh.nodes.capacity() / 2));
  // The new nodes numbered in vertex order, then placed in space on threads (each node on
  // its own: the same coordinates for any count).
  sm_out.interior_nodes.reserve(nv - std::min(nv, f.fixed_count));
  for (std::uint32_t v = f.fixed_count; v < nv; ++v) {
    if (f.global[v] != kNoLocal) continue;
    f.global[v] = static_cast<std::uint32_t>(f.mesh.nodes.size() + sm_out.interior_nodes.size());
    sm_out.interior_nodes.push_back(v);   // the local vertex until placed
  }
  const std::size_t first_new = f.mesh.nodes.size();
  f.mesh.nodes.resize(first_new + sm_out.interior_nodes.size());
  parallel_for_chunks(resolve_thread_count(f.opt.threads), sm_out.interior_nodes.size(), kOutputNodeChunk,
                      [&](std::size_t begin, std::size_t end) {
                        for (std::size_t k = begin; k < end; ++k) {
                          const Vec2 p = xy[sm_out.interior_nodes[k]];
                          MeshNode& n = f.mesh.nodes[first_new + k];
                          n.xyz = f.plane.to_space(p);
                          if (f.plane.geom) n.uv = f.plane.to_param(p), n.has_uv = true;
                          sm_out.interior_nodes[k] = static_cast<std::uint32_t>(first_new + k);
                        }
                      });
  const bool flip = f.plane.geom && !f.plane.ccw_is_outward;
  std::vector<std::array<std::uint32_t, 4>> local_quads;
  if (f.recombined()) {
    std::vector<Vec3> xyz(nv);
    for (std::uint32_t v = 0; v < nv; ++v) xyz[v] = f.mesh.nodes[f.global[v]].xyz;
    // Embedded curves stay edges of the mesh.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> fixed;
    for (const FaceChain& ch : f.emb_curves)
      for (std::size_t k = 0; k + 1 < ch.nodes.size(); ++k)
        fixed.push_back(std::minmax(f.local_of[ch.nodes[k]], f.local_of[ch.nodes[k + 1]]));
    std::sort(fixed.begin(), fixed.end());
    RecombineOptions ro;
    ro.algorithm = f.opt.constraints->algorithm;
    RecombineResult rr = recombine(local, xyz, xy, fixed, ro);
    local = std::move(rr.triangles);
    local_quads = std::move(rr.quads);
  }
  xy = {};
  if (local_quads.empty() && !f.has_layers()) {
    // The common case: the local triangles become the surface's in place (a second
    // array of 12 bytes a triangle otherwise).
    for (auto& t : local) {
      const std::uint32_t a = f.global[t[0]], b = f.global[t[1]], c = f.global[t[2]];
      t = flip ? std::array<std::uint32_t, 3>{a, c, b} : std::array<std::uint32_t, 3>{a, b, c};
    }
    sm_out.triangles = std::move(local);
  } else {
    append_elements(sm_out, local, local_quads, flip, f.global);
  }
  // The boundary layers' elements (face_layer.h), already on global nodes.
  std::vector<std::uint32_t> identity;
  if (f.has_layers()) {
    identity.resize(f.mesh.nodes.size());
    for (std::uint32_t v = 0; v < identity.size(); ++v) identity[v] = v;
    append_elements(sm_out, f.layer_triangles, f.layer_quads, flip, identity);
    sm_out.interior_nodes.insert(sm_out.interior_nodes.end(), f.layer_nodes.begin(), f.layer_nodes.end());
  }
  store_surface(f, std::move(sm_out));
  f.res.target_sizes.push_back({f.tag, target_size_fn(f.sizing)});
}

}  // namespace sm
