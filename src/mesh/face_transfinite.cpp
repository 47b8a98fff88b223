// A transfinite face: the boundary chain, its corners and the filled grid in the face's
// plane or in space (face_transfinite.h).
#include "mesh/face_transfinite.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "exact/predicates.h"
#include "mesh/face_boundary.h"
#include "mesh/face_output.h"
#include "mesh/transfinite_surface.h"

namespace sm {

namespace {

// The filling's fault as the face's problem, with its values.
bool fail_transfinite(FaceWork& f, const TransfiniteResult& r) {
  MeshProblem p = MeshProblem::TransfiniteEmptySide;
  switch (r.fault) {
    case TransfiniteFault::CornerCount: p = MeshProblem::TransfiniteCornerCount; break;
    case TransfiniteFault::CornerOffBoundary: p = MeshProblem::TransfiniteCornerOffBoundary; break;
    case TransfiniteFault::CornerTwice: p = MeshProblem::TransfiniteCornerTwice; break;
    case TransfiniteFault::SidesUnequal4: p = MeshProblem::TransfiniteSidesUnequal4; break;
    case TransfiniteFault::SidesUnequal3: p = MeshProblem::TransfiniteSidesUnequal3; break;
    case TransfiniteFault::EmptySide:
    case TransfiniteFault::None: break;
  }
  return f.fail(p, {r.numbers[0], r.numbers[1], r.numbers[2], r.numbers[3]});
}

}  // namespace

bool mesh_transfinite_face(FaceWork& f, const geo::ModelSurface& s, const TransfiniteSurfaceSpec& spec) {
  if (!collect_boundary(f, s)) return false;
  if (f.chains.size() != 1) {
    const std::size_t holes = f.chains.size() - 1;
    return f.fail(MeshProblem::TransfiniteHoles, {static_cast<long long>(holes)});
  }
  const FaceChain& ch = f.chains[0];
  const std::size_t n = ch.nodes.size();
  // A filling Surface has no plane: it is interpolated in space (onto its sphere when it
  // has one); a Plane Surface in its plane (a PolarSphere's stereographic plane).
  const bool in_plane = !s.filling;
  if (in_plane && !choose_plane(f)) return false;
  TransfiniteBoundary b;
  b.coords.reserve(n), b.xyz.reserve(n);
  for (std::uint32_t node : ch.nodes) {
    const MeshNode& mn = f.mesh.nodes[node];
    b.xyz.push_back(mn.xyz);
    if (in_plane) {
      const Vec2 p = f.plane.node_plane(mn);
      b.coords.push_back({p.x, p.y, 0.0});
    } else {
      b.coords.push_back(mn.xyz);
    }
  }
  if (spec.corners.empty()) {
    std::vector<std::size_t> starts;
    for (std::size_t k = 0; k < n; ++k)
      if (k == 0 || ch.edge_curve[k] != ch.edge_curve[k - 1]) starts.push_back(k);
    b.corners = implicit_transfinite_corners(starts, n);
  } else {
    for (int corner : spec.corners) {
      const auto it = f.mesh.vertex_node.find(corner);
      const auto at =
          it == f.mesh.vertex_node.end() ? ch.nodes.end() : std::find(ch.nodes.begin(), ch.nodes.end(), it->second);
      if (at == ch.nodes.end())
        return f.fail(MeshProblem::TransfiniteCorner, {corner});
      b.corners.push_back(static_cast<std::size_t>(at - ch.nodes.begin()));
    }
  }
  const int smoothing = f.opt.smoothing > 1 ? f.opt.smoothing : 0;  // Gmsh: with Mesh.Smoothing > 1
  TransfiniteResult r = fill_transfinite(b, spec.arrangement, f.recombined(), smoothing);
  if (!r.ok()) return fail_transfinite(f, r);
  std::optional<Vec3> centre;
  double radius = 0;
  if (s.filling && s.sphere_centre)
    if (const geo::ModelVertex* c = f.model.vertex(s.sphere_centre)) centre = c->xyz, radius = norm(b.xyz[0] - c->xyz);
  SurfaceMesh out;
  out.tag = f.tag;
  std::vector<std::uint32_t> id(ch.nodes.begin(), ch.nodes.end());
  for (const Vec3& p : r.interior) {
    std::uint32_t node;
    if (in_plane) {
      const Vec2 q{p.x, p.y};
      node = f.plane.geom ? f.mesh.add_node(f.plane.to_space(q), f.plane.to_param(q))
                          : f.mesh.add_node(f.plane.to_space(q));
    } else {
      Vec3 x = p;
      if (centre && norm(x - *centre) > 0) x = *centre + (radius / norm(x - *centre)) * (x - *centre);
      node = f.mesh.add_node(x);
    }
    id.push_back(node);
    out.interior_nodes.push_back(node);
  }
  // Counter-clockwise in the plane: the elements run as the boundary chain does, which a
  // Euclidean plane's basis makes counter-clockwise; on a geometry the chain may turn
  // either way, so the elements' own majority decides. Then the orientation rule of
  // output_face(). A filling surface keeps its loop's orientation.
  bool flip = false;
  if (in_plane && f.plane.geom) {
    long turn = 0;
    auto P = [&](std::uint32_t k) {
      return k < n ? Vec2{b.coords[k].x, b.coords[k].y} : Vec2{r.interior[k - n].x, r.interior[k - n].y};
    };
    for (const auto& t : r.triangles) turn += static_cast<int>(orient2d(P(t[0]), P(t[1]), P(t[2])));
    for (const auto& q : r.quads) turn += static_cast<int>(orient2d(P(q[0]), P(q[1]), P(q[2])));
    flip = (turn < 0) != !f.plane.ccw_is_outward;
  }
  append_elements(out, r.triangles, r.quads, flip, id);
  ++f.res.stats.transfinite_faces;
  store_surface(f, std::move(out));
  return true;
}

}  // namespace sm
