// Removing the nodes behind too short Courant steps (see time_step_repair.h).
#include "mesh/time_step_repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <tuple>

#include "exact/predicates.h"

namespace sm {

namespace {

// A triangle of the model mesh: its surface (index in map order) and its index there.
struct StepTri {
  std::uint32_t surface, index;
};

struct StepWork {
  ModelMesh& mesh;
  std::span<const double> depth;
  const TimeStepOptions& opt;
  std::vector<SurfaceMesh*> surfaces;
  std::vector<std::vector<std::uint8_t>> dead;      // per surface, per triangle
  std::vector<std::uint8_t> model_vertex;           // per node
  // Per node on a curve's inside (not its ends): the curve's tag; 0 elsewhere, -1 on two.
  std::vector<int> curve_of;

  double node_depth(std::uint32_t v) const { return v < depth.size() ? depth[v] : 0.0; }
  std::array<std::uint32_t, 3>& tri(StepTri t) const { return surfaces[t.surface]->triangles[t.index]; }
  double step(const std::array<std::uint32_t, 3>& t) const {
    return triangle_time_step(mesh.nodes[t[0]].xyz, mesh.nodes[t[1]].xyz, mesh.nodes[t[2]].xyz, node_depth(t[0]),
                              node_depth(t[1]), node_depth(t[2]), opt);
  }
  double length(std::uint32_t a, std::uint32_t b) const {
    return time_step_edge_length(mesh.nodes[a].xyz, mesh.nodes[b].xyz, opt);
  }
};

bool holds(const std::array<std::uint32_t, 3>& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

// Whether collapsing v onto w is valid (time_step_repair.h); `ball_v`/`ball_w` the live
// triangles of v and w. On success the smallest step of the changed triangles after it.
bool try_collapse(StepWork& w_, std::uint32_t v, std::uint32_t w, const std::vector<StepTri>& ball_v,
                  const std::vector<StepTri>& ball_w, double before, double* after) {
  const ModelMesh& m = w_.mesh;
  if (w_.model_vertex[v] || w_.curve_of[v] < 0) return false;
  if (!m.nodes[v].has_uv || !m.nodes[w].has_uv) return false;
  const std::uint32_t s = ball_v.front().surface;
  for (const StepTri& t : ball_v)
    if (t.surface != s) return false;
  if (!w_.surfaces[s]->quads.empty()) return false;
  if (w_.curve_of[v] > 0) {   // on a curve: w must be its neighbour along it
    const CurveMesh& c = m.curves.at(w_.curve_of[v]);
    const auto it = std::find(c.nodes.begin(), c.nodes.end(), v);
    if (it == c.nodes.end() || it == c.nodes.begin() || it + 1 == c.nodes.end()) return false;
    if (*(it - 1) != w && *(it + 1) != w) return false;
    const bool closed = c.nodes.front() == c.nodes.back();
    if (c.nodes.size() < (closed ? 5u : 3u)) return false;   // a closed curve keeps 3 edges
  }
  // Link condition: the common neighbours of v and w are the apexes of the edge's triangles.
  std::vector<std::uint32_t> nv, nw, apex;
  for (const StepTri& t : ball_v)
    for (std::uint32_t x : w_.tri(t))
      if (x != v) nv.push_back(x);
  for (const StepTri& t : ball_w)
    for (std::uint32_t x : w_.tri(t))
      if (x != w) nw.push_back(x);
  for (const StepTri& t : ball_v)
    if (holds(w_.tri(t), w))
      for (std::uint32_t x : w_.tri(t))
        if (x != v && x != w) apex.push_back(x);
  if (apex.empty()) return false;
  for (auto* l : {&nv, &nw, &apex}) {
    std::sort(l->begin(), l->end());
    l->erase(std::unique(l->begin(), l->end()), l->end());
  }
  std::vector<std::uint32_t> common;
  std::set_intersection(nv.begin(), nv.end(), nw.begin(), nw.end(), std::back_inserter(common));
  std::erase(common, w);
  if (common != apex) return false;
  // Orientation kept, and the steps of the triangles v leaves to w.
  double least = std::numeric_limits<double>::infinity();
  std::size_t kept = 0;
  for (const StepTri& t : ball_v) {
    std::array<std::uint32_t, 3> tri = w_.tri(t);
    if (holds(tri, w)) continue;
    const Sign was = orient2d(m.nodes[tri[0]].uv, m.nodes[tri[1]].uv, m.nodes[tri[2]].uv);
    for (std::uint32_t& x : tri)
      if (x == v) x = w;
    const Sign now = orient2d(m.nodes[tri[0]].uv, m.nodes[tri[1]].uv, m.nodes[tri[2]].uv);
    if (was == Sign::Zero || now != was) return false;
    least = std::min(least, w_.step(tri));
    ++kept;
  }
  if (kept == 0 || !(least > before)) return false;
  *after = least;
  return true;
}

// Makes the collapse of v onto w: the triangles holding both die, the others take w.
void make_collapse(StepWork& w_, std::uint32_t v, std::uint32_t w, const std::vector<StepTri>& ball_v) {
  ModelMesh& m = w_.mesh;
  for (const StepTri& t : ball_v) {
    auto& tri = w_.tri(t);
    if (holds(tri, w)) {
      w_.dead[t.surface][t.index] = 1;
      continue;
    }
    for (std::uint32_t& x : tri)
      if (x == v) x = w;
  }
  SurfaceMesh& sf = *w_.surfaces[ball_v.front().surface];
  std::erase(sf.interior_nodes, v);
  if (w_.curve_of[v] > 0) {
    CurveMesh& c = m.curves.at(w_.curve_of[v]);
    const auto i = static_cast<std::ptrdiff_t>(std::find(c.nodes.begin(), c.nodes.end(), v) - c.nodes.begin());
    c.nodes.erase(c.nodes.begin() + i);
    if (static_cast<std::size_t>(i) < c.t.size()) c.t.erase(c.t.begin() + i);
    if (static_cast<std::size_t>(i) < c.h.size()) c.h.erase(c.h.begin() + i);
  }
}

}  // namespace

StepRepairResult repair_short_steps(ModelMesh& mesh, std::span<const double> node_depth, double min_dt,
                                    const TimeStepOptions& opt, std::size_t max_rounds, std::size_t max_collapses) {
  StepRepairResult out;
  if (!(min_dt > 0)) return out;
  StepWork w{mesh, node_depth, opt, {}, {}, {}, {}};
  for (auto& [tag, sf] : mesh.surfaces) w.surfaces.push_back(&sf);
  const std::size_t n = mesh.nodes.size();
  w.model_vertex.assign(n, 0);
  for (const auto& [tag, v] : mesh.vertex_node)
    if (v < n) w.model_vertex[v] = 1;
  w.curve_of.assign(n, 0);
  for (const auto& [tag, c] : mesh.curves) {
    for (std::size_t i = 0; i < c.nodes.size(); ++i) {
      const std::uint32_t v = c.nodes[i];
      if (v >= n) continue;
      const bool end = i == 0 || i + 1 == c.nodes.size();
      w.curve_of[v] = end || w.curve_of[v] != 0 ? -1 : tag;
    }
  }
  for (std::size_t round = 0; round < max_rounds && out.removed.size() < max_collapses; ++round) {
    // The short triangles, shortest step first.
    std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> bad;
    for (std::uint32_t s = 0; s < w.surfaces.size(); ++s) {
      const auto& tris = w.surfaces[s]->triangles;
      for (std::uint32_t i = 0; i < tris.size(); ++i)
        if (const double st = w.step(tris[i]); st < min_dt) bad.emplace_back(st, s, i);
    }
    if (bad.empty()) break;
    std::sort(bad.begin(), bad.end());
    // The balls of the nodes of their edges, in one pass over the triangles.
    std::map<std::uint32_t, std::vector<StepTri>> balls;
    for (const auto& [st, s, i] : bad)
      for (std::uint32_t v : w.surfaces[s]->triangles[i]) balls[v];
    for (std::uint32_t s = 0; s < w.surfaces.size(); ++s) {
      const auto& tris = w.surfaces[s]->triangles;
      for (std::uint32_t i = 0; i < tris.size(); ++i)
        for (std::uint32_t v : tris[i])
          if (const auto it = balls.find(v); it != balls.end()) it->second.push_back({s, i});
    }
    w.dead.assign(w.surfaces.size(), {});
    for (std::size_t s = 0; s < w.surfaces.size(); ++s) w.dead[s].assign(w.surfaces[s]->triangles.size(), 0);
    // Nodes whose ball changed this round: their lists are stale until the next round.
    std::vector<std::uint8_t> touched(n, 0);
    std::size_t made = 0;
    for (const auto& [st, s, i] : bad) {
      if (out.removed.size() >= max_collapses) break;
      if (w.dead[s][i]) continue;
      const auto t = w.surfaces[s]->triangles[i];
      if (touched[t[0]] || touched[t[1]] || touched[t[2]]) continue;
      // Its edges shortest first; each end tried as the node removed.
      std::array<std::pair<double, int>, 3> edges;
      for (int e = 0; e < 3; ++e) edges[e] = {w.length(t[e], t[(e + 1) % 3]), e};
      std::sort(edges.begin(), edges.end());
      bool done = false;
      for (const auto& [len, e] : edges) {
        if (done) break;
        const std::uint32_t a = t[e], b = t[(e + 1) % 3];
        for (const auto& [v, to] : {std::pair{a, b}, std::pair{b, a}}) {
          double after = 0;
          if (!try_collapse(w, v, to, balls.at(v), balls.at(to), st, &after)) continue;
          for (const StepTri& bt : balls.at(v))
            for (std::uint32_t x : w.tri(bt)) touched[x] = 1;
          for (const StepTri& bt : balls.at(to))
            for (std::uint32_t x : w.tri(bt)) touched[x] = 1;
          out.removed.push_back({mesh.nodes[v].xyz, w.surfaces[s]->tag, len, st});
          make_collapse(w, v, to, balls.at(v));
          ++made;
          done = true;
          break;
        }
      }
    }
    for (std::size_t s = 0; s < w.surfaces.size(); ++s) {
      auto& tris = w.surfaces[s]->triangles;
      std::size_t k = 0;
      for (std::size_t i = 0; i < tris.size(); ++i)
        if (!w.dead[s][i]) tris[k++] = tris[i];
      tris.resize(k);
    }
    ++out.rounds;
    if (made == 0) break;
  }
  return out;
}

}  // namespace sm
