// Structured meshes of extruded entities (mesh/extrude_mesh.h).
#include "mesh/extrude_mesh.h"

#include <algorithm>
#include <cstdlib>
#include <map>

#include <fmt/format.h>

#include "mesh/face_output.h"

namespace sm {

namespace {

const geo::Extrusion* layered(const geo::Model& model, int dim, int tag) {
  const geo::Extrusion* ex = model.extrusion(dim, tag);
  return ex && ex->spec.layered ? ex : nullptr;
}

}  // namespace

bool extruded_curve_nodes(const geo::Model& model, const ModelMesh& mesh, int tag, std::vector<double>& ts,
                          std::vector<Vec3>& xyz) {
  const geo::Extrusion* ex = layered(model, 1, tag);
  if (!ex) return false;
  if (ex->body) {   // swept from point ex->source
    const geo::ModelVertex* p = model.vertex(ex->source);
    if (!p) return false;
    const std::vector<double> fr = ex->spec.layers.fractions();
    ts.assign(fr.begin(), fr.end());
    ts.back() = 1.0;   // the curve's end vertex
    xyz.clear();
    for (std::size_t k = 1; k + 1 < fr.size(); ++k) xyz.push_back(geo::extrude_point(ex->spec, p->xyz, fr[k]));
    return true;
  }
  // A top copy: its source's nodes (a copy runs as its source) moved by the whole extrusion.
  const auto src = mesh.curves.find(std::abs(ex->source));
  if (src == mesh.curves.end() || src->second.nodes.size() < 2) return false;
  ts = src->second.t;
  xyz.clear();
  const double top = ex->spec.layers.fractions().back();
  for (std::size_t i = 1; i + 1 < src->second.nodes.size(); ++i)
    xyz.push_back(geo::extrude_point(ex->spec, mesh.nodes[src->second.nodes[i]].xyz, top));
  return true;
}

bool is_layered_extrusion(const geo::Model& model, int surface) { return layered(model, 2, surface) != nullptr; }

namespace {

bool mesh_swept_face(FaceWork& f, const geo::Extrusion& ex) {
  const std::vector<double> fr = ex.spec.layers.fractions();
  const std::size_t K = fr.size() - 1;
  const std::vector<std::uint32_t> src = f.mesh.curve_nodes(ex.source);
  const std::vector<std::uint32_t> top = f.mesh.curve_nodes(ex.source > 0 ? ex.top : -ex.top);
  if (src.size() < 2 || top.size() != src.size())
    return f.fail(MeshProblem::ExtrudeTopNodes,
                  {ex.top, static_cast<long long>(top.size()), std::abs(ex.source), static_cast<long long>(src.size())},
                  std::nullopt, {ex.top, std::abs(ex.source)});
  const std::size_t M = src.size() - 1;
  auto side = [&](int curve, std::uint32_t base) -> std::vector<std::uint32_t> {
    if (!curve) return std::vector<std::uint32_t>(K + 1, base);
    return f.mesh.curve_nodes(curve);
  };
  const std::vector<std::uint32_t> left = side(ex.begin_curve, src.front());
  const std::vector<std::uint32_t> right = side(ex.end_curve, src.back());
  if (left.size() != K + 1 || right.size() != K + 1)
    return f.fail(MeshProblem::ExtrudeSweptElements, {std::abs(ex.source), static_cast<long long>(K)}, std::nullopt,
                  {ex.begin_curve, ex.end_curve});
  SurfaceMesh out;
  out.tag = f.tag;
  // grid[k * (M + 1) + i]: source node i at layer height k.
  std::vector<std::uint32_t> grid((K + 1) * (M + 1));
  for (std::size_t k = 0; k <= K; ++k)
    for (std::size_t i = 0; i <= M; ++i) {
      std::uint32_t n;
      if (k == 0) n = src[i];
      else if (k == K) n = top[i];
      else if (i == 0) n = left[k];
      else if (i == M) n = right[k];
      else {
        n = f.mesh.add_node(geo::extrude_point(ex.spec, f.mesh.nodes[src[i]].xyz, fr[k]));
        out.interior_nodes.push_back(n);
      }
      grid[k * (M + 1) + i] = n;
    }
  for (std::size_t k = 0; k < K; ++k)
    for (std::size_t i = 0; i < M; ++i) {
      const std::array<std::uint32_t, 4> q{grid[k * (M + 1) + i], grid[k * (M + 1) + i + 1],
                                          grid[(k + 1) * (M + 1) + i + 1], grid[(k + 1) * (M + 1) + i]};
      // A cell with a corner twice (on the rotation axis) closes into a triangle.
      std::array<std::uint32_t, 4> d{};
      std::size_t nd = 0;
      for (std::size_t c = 0; c < 4; ++c)
        if (std::find(d.begin(), d.begin() + nd, q[c]) == d.begin() + nd) d[nd++] = q[c];
      if (nd == 3) {
        out.triangles.push_back({d[0], d[1], d[2]});
      } else if (nd == 4) {
        if (ex.spec.recombine) {
          out.quads.push_back(q);
        } else {
          out.triangles.push_back({q[0], q[1], q[2]});
          out.triangles.push_back({q[0], q[2], q[3]});
        }
      }
    }
  store_surface(f, std::move(out));
  return true;
}

bool mesh_top_face(FaceWork& f, const geo::ModelSurface& s, const geo::Extrusion& ex) {
  const auto sit = f.mesh.surfaces.find(std::abs(ex.source));
  if (sit == f.mesh.surfaces.end())
    return f.fail(MeshProblem::SourceNotMeshed, {std::abs(ex.source)});
  // Source node -> top node, along the copied boundary curves.
  std::map<std::uint32_t, std::uint32_t> to_top;
  for (int l : s.loops)
    for (int c : f.model.curve_loop(l)->curves) {
      const geo::Extrusion* ce = f.model.extrusion(1, c);
      const auto tm = f.mesh.curves.find(std::abs(c));
      if (!ce || ce->body || tm == f.mesh.curves.end()) continue;
      const auto sm = f.mesh.curves.find(std::abs(ce->source));
      if (sm == f.mesh.curves.end() || sm->second.nodes.size() != tm->second.nodes.size())
        return f.fail(MeshProblem::ExtrudeCurveNotCopy, {std::abs(c), std::abs(ce->source)}, std::nullopt,
                      {std::abs(c)});
      for (std::size_t j = 0; j < sm->second.nodes.size(); ++j) to_top[sm->second.nodes[j]] = tm->second.nodes[j];
    }
  const SurfaceMesh& from = sit->second;
  SurfaceMesh out;
  out.tag = f.tag;
  const double h = ex.spec.layers.fractions().back();
  for (std::uint32_t n : from.interior_nodes) {
    const std::uint32_t m = f.mesh.add_node(geo::extrude_point(ex.spec, f.mesh.nodes[n].xyz, h));
    to_top[n] = m;
    out.interior_nodes.push_back(m);
  }
  auto map = [&](std::uint32_t n, std::uint32_t& m) {
    const auto it = to_top.find(n);
    if (it == to_top.end()) return false;
    m = it->second;
    return true;
  };
  for (const auto& t : from.triangles) {
    std::array<std::uint32_t, 3> o{};
    for (std::size_t c = 0; c < 3; ++c)
      if (!map(t[c], o[c])) return f.fail(MeshProblem::ExtrudeNodeNoCopy, {std::abs(ex.source)});
    out.triangles.push_back(o);
  }
  for (const auto& q : from.quads) {
    std::array<std::uint32_t, 4> o{};
    for (std::size_t c = 0; c < 4; ++c)
      if (!map(q[c], o[c])) return f.fail(MeshProblem::ExtrudeNodeNoCopy, {std::abs(ex.source)});
    out.quads.push_back(o);
  }
  store_surface(f, std::move(out));
  return true;
}

}  // namespace

bool mesh_extruded_face(FaceWork& f, const geo::ModelSurface& s) {
  const geo::Extrusion* ex = layered(f.model, 2, s.tag);
  if (!ex) return false;
  return ex->body ? mesh_swept_face(f, *ex) : mesh_top_face(f, s, *ex);
}

}  // namespace sm
