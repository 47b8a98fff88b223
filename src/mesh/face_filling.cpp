// Step 2 of a filling Surface: its plane, or its patch's (face_filling.h).
#include "mesh/face_filling.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/filling_map.h"

namespace sm {

void choose_filling_plane(FaceWork& f, const geo::ModelSurface& s) {
  geo::TransfinitePatch patch = f.model.filling_patch(s);
  const double tol = std::max(f.model.options().tolerance * f.bbox, 1e-12 * f.bbox);
  if (!patch.sphere_centre) {
    std::vector<const std::vector<std::uint32_t>*> curves;
    for (const auto* group : {&f.chains, &f.emb_curves})
      for (const FaceChain& ch : *group) curves.push_back(&ch.nodes);
    FacePlane flat;
    if (!make_face_plane(flat, f.mesh, curves, f.emb_points, tol)) {
      f.plane = flat;
      return;
    }
  }
  auto map = std::make_shared<FillingMap>(std::move(patch));
  const geo::TransfinitePatch& p = map->patch();
  // The outer chain: each node on the curve of the edge it starts, at that curve's
  // parameter, which is the side's (reversed when the loop runs the curve backwards).
  const FaceChain& outer = f.chains[0];
  std::unordered_map<int, std::size_t> side_of;  // curve tag -> side
  for (std::size_t i = 0; i < p.sides.size(); ++i)
    for (int c : f.model.curve_loop(std::abs(s.loops[0]))->curves)
      if (const geo::ModelCurve* mc = f.model.curve(std::abs(c)); mc && mc->shape && &*mc->shape == p.sides[i].curve)
        side_of[std::abs(c)] = i;
  // Placed points that miss the node by more than this (a parameter that is not the
  // side's) are not kept: such nodes are projected as the others.
  const double place_tol = std::max(1e3 * tol, 1e-9 * f.bbox);
  FillingMap& m = *map;
  std::unordered_map<std::uint64_t, double> t_of;  // (curve, node) -> the curve's parameter
  for (const auto& [c, side] : side_of)
    if (const auto cm = f.mesh.curves.find(c); cm != f.mesh.curves.end())
      for (std::size_t j = 0; j < cm->second.nodes.size(); ++j)
        t_of[(static_cast<std::uint64_t>(c) << 32) | cm->second.nodes[j]] = cm->second.t[j];
  for (std::size_t k = 0; k < outer.nodes.size(); ++k) {
    const int c = outer.edge_curve[k];
    const auto side = side_of.find(c);
    const auto t = t_of.find((static_cast<std::uint64_t>(c) << 32) | outer.nodes[k]);
    if (side == side_of.end() || t == t_of.end()) continue;
    const Vec2 q = m.side_point(side->second, p.sides[side->second].reversed ? 1 - t->second : t->second);
    const Vec3 x = f.mesh.nodes[outer.nodes[k]].xyz;
    if (norm(m.point(q) - x) <= place_tol) m.remember(x, q);
  }
  // Every other node (holes, embedded points and curves, as Gmsh reparametrises them onto
  // the face) by projection onto the patch: its closest point.
  f.plane = FacePlane{};
  f.plane.filling = map;
}

}  // namespace sm
