// Steps 1 and 2 of a face: the boundary chains and the face's plane (face_boundary.h).
#include "mesh/face_boundary.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mesh/face_plane.h"

namespace sm {

bool collect_boundary(FaceWork& f, const geo::ModelSurface& s) {
  // Islands below the mesh size (hole chains of fewer than 3 mesh edges): one warning
  // for the face, naming the largest, rather than one line per island.
  struct Island {
    int loop;
    double span;  // distance between its nodes: a lower bound of its size
    Vec3 at;
  };
  std::vector<Island> islands;
  for (std::size_t li = 0; li < s.loops.size(); ++li) {
    const geo::ModelCurveLoop* loop = f.model.curve_loop(std::abs(s.loops[li]));
    if (!loop) return f.fail(MeshProblem::LoopMissing, {std::abs(s.loops[li])});
    std::vector<int> curves = loop->curves;
    if (s.loops[li] < 0) {
      std::reverse(curves.begin(), curves.end());
      for (int& c : curves) c = -c;
    }
    // A loop may hold several closed chains (Gmsh's subloops): a chain ends when it
    // returns to its first node.
    FaceChain ch;
    for (int sc : curves) {
      const auto it = f.mesh.curves.find(std::abs(sc));
      if (it == f.mesh.curves.end()) return f.fail(MeshProblem::CurveNotMeshed, {std::abs(sc)});
      std::vector<std::uint32_t> nodes = it->second.nodes;
      if (nodes.size() < 2) continue;  // collapsed (mesh/mesh1d.cpp): its ends are one node
      if (sc < 0) std::reverse(nodes.begin(), nodes.end());
      if (!ch.nodes.empty() && ch.nodes.back() != nodes.front())
        return f.fail(MeshProblem::LoopNotConnected, {loop->tag, sc});
      for (std::size_t k = ch.nodes.empty() ? 0 : 1; k < nodes.size(); ++k) ch.nodes.push_back(nodes[k]);
      ch.edge_curve.insert(ch.edge_curve.end(), nodes.size() - 1, std::abs(sc));
      if (ch.nodes.size() > 1 && ch.nodes.back() == ch.nodes.front()) {
        ch.nodes.pop_back();
        if (ch.nodes.size() < 3 && (li > 0 || !f.chains.empty())) {
          // An island below the mesh size meshed as two edges encloses nothing: left out
          // (Gmsh does the same).
          const Vec3 a = f.mesh.nodes[ch.nodes.front()].xyz, b = f.mesh.nodes[ch.nodes.back()].xyz;
          islands.push_back({loop->tag, norm(b - a), (a + b) * 0.5});
        } else if (ch.nodes.size() < 3) {
          return f.fail(MeshProblem::LoopTooFewNodes, {loop->tag}, f.mesh.nodes[ch.nodes.front()].xyz);
        } else {
          f.chains.push_back(std::move(ch));
        }
        ch = FaceChain{};
      }
    }
    if (!ch.nodes.empty()) return f.fail(MeshProblem::LoopNotClosed, {loop->tag});
  }
  if (!islands.empty()) {
    // The first island of the largest span: deterministic for equal spans.
    std::size_t big = 0;
    for (std::size_t i = 1; i < islands.size(); ++i)
      if (islands[i].span > islands[big].span) big = i;
    MeshNote note{.kind = MeshNoteKind::IslandsLeftOut, .surface = f.tag, .place = f.place_of(islands[big].at)};
    for (const auto& island : islands) note.loops.push_back(island.loop);
    f.res.notes.push_back(std::move(note));
  }
  if (f.chains.empty()) return f.fail(MeshProblem::NoBoundaryLoop);
  for (int p : s.embedded_points) {
    const auto it = f.mesh.vertex_node.find(p);
    if (it == f.mesh.vertex_node.end()) return f.fail(MeshProblem::EmbeddedPointNoNode, {p});
    f.emb_points.push_back(it->second);
  }
  for (int c : s.embedded_curves) {
    const auto it = f.mesh.curves.find(c);
    if (it == f.mesh.curves.end()) return f.fail(MeshProblem::EmbeddedCurveNotMeshed, {c});
    FaceChain ch;
    ch.nodes = it->second.nodes;
    ch.edge_curve.assign(ch.nodes.size() - 1, c);
    f.emb_curves.push_back(std::move(ch));
  }
  return true;
}

bool choose_plane(FaceWork& f) {
  std::vector<const std::vector<std::uint32_t>*> curves;
  for (const auto* group : {&f.chains, &f.emb_curves})
    for (const FaceChain& ch : *group) curves.push_back(&ch.nodes);
  const double tol = std::max(f.model.options().tolerance * f.bbox, 1e-12 * f.bbox);
  // Gmsh meshes a Plane Surface in its mean plane however far its boundary lies off it,
  // and only checks (in a debug message) that no point is off by more than 1e-3 of the
  // bounding box's diagonal. Within that bound we mesh in the plane too, with a warning;
  // beyond it the boundary is taken for a mistake.
  constexpr double kGmshPlaneCoherence = 1e-3;
  std::optional<FacePlaneOffset> off;
  const std::optional<FacePlaneProblem> p =
      make_face_plane(f.plane, f.mesh, curves, f.emb_points, tol, kGmshPlaneCoherence * f.bbox, &off);
  if (p)
  {
    constexpr MeshProblem kProblem[] = {MeshProblem::FaceAtPole, MeshProblem::FaceNoArea, MeshProblem::FaceNotPlanar,
                                        MeshProblem::FacePointOffPlane};
    f.fail(kProblem[static_cast<int>(p->fault)], {}, p->where);
    f.res.error.value = kGmshPlaneCoherence;
    return false;
  }
  if (off)
    f.res.notes.push_back(MeshNote{.kind = MeshNoteKind::BoundaryOffPlane,
                                   .surface = f.tag,
                                   .place = f.place_of(off->where),
                                   .distance = off->distance,
                                   .relative = off->distance / f.bbox});
  return true;
}

}  // namespace sm
