// Compound surfaces: the union of a group's plane surfaces as one plane surface of a
// copy of the model, and the union's elements put back on the originals
// (compound_surface.h says what Gmsh 4.8.4 does and what we do).
#include "mesh/compound_surface.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "exact/ring.h"

namespace sm {

namespace {

std::string tag_list(const std::vector<int>& tags) {
  std::string s;
  for (int t : tags) s += fmt::format("{}{}", s.empty() ? "" : ", ", t);
  return s;
}

// Points along a loop's curves in the loop's order (each curve from its start as the
// loop runs it), 16 intervals per curve.
void sample_loop(const geo::Model& m, const geo::ModelCurveLoop& loop, std::vector<Vec3>& out) {
  constexpr int kSamples = 16;
  for (int c : loop.curves) {
    const geo::ModelCurve* mc = m.curve(std::abs(c));
    if (!mc || !mc->shape) continue;
    for (int k = 0; k < kSamples; ++k) {
      const double t = static_cast<double>(k) / kSamples;
      out.push_back(mc->shape->point(c > 0 ? t : 1 - t));
    }
  }
}

struct Union {
  std::vector<std::vector<int>> chains;   // closed chains of signed boundary curves
  int geometry = 0;
  Vec3 normal{0, 0, 1};
};

// Why the surfaces cannot be combined here (empty: they can, `u` filled).
std::string check_union(const geo::Model& m, const std::vector<int>& tags, Union& u) {
  const geo::ModelSurface* first = m.surface(tags[0]);
  u.geometry = first->geometry;
  for (int t : tags) {
    const geo::ModelSurface* s = m.surface(t);
    if (s->geometry != u.geometry) return "the surfaces are not on one surface geometry";
  }
  // One plane: Newell's normal of the first surface's outer loop, every loop within a
  // millionth of the points' extent of it.
  std::vector<Vec3> outer, all;
  if (const geo::ModelCurveLoop* l = first->loops.empty() ? nullptr : m.curve_loop(std::abs(first->loops[0])))
    sample_loop(m, *l, outer);
  for (int t : tags)
    for (int l : m.surface(t)->loops)
      if (const geo::ModelCurveLoop* loop = m.curve_loop(std::abs(l))) sample_loop(m, *loop, all);
  if (u.geometry == 0) {
    Vec3 n{0, 0, 0};
    for (std::size_t i = 0; i < outer.size(); ++i) n = n + cross(outer[i], outer[(i + 1) % outer.size()]);
    geo::BoundingBox box;
    for (const Vec3& p : all) box.add(p);
    const double len = norm(n);
    if (!(len > 0) || all.empty()) return fmt::format("surface {} has no plane", tags[0]);
    u.normal = (1.0 / len) * n;
    const double tol = 1e-6 * box.diagonal();
    for (const Vec3& p : all)
      if (std::fabs(dot(u.normal, p - all[0])) > tol)
        return "the surfaces are not in one plane (Gmsh reparametrises such a compound; stereomesh combines "
               "surfaces of one plane only)";
  }
  // The boundary: curves in exactly one of the surfaces' loops.
  std::map<int, std::pair<int, int>> uses;   // |curve| -> (count, signed tag)
  for (int t : tags)
    for (int l : m.surface(t)->loops)
      if (const geo::ModelCurveLoop* loop = m.curve_loop(std::abs(l)))
        for (int c : loop->curves) {
          auto& [count, signed_tag] = uses[std::abs(c)];
          ++count;
          signed_tag = c;
        }
  std::vector<int> bnd;
  for (const auto& [c, use] : uses)
    if (use.first == 1) bnd.push_back(c);
  if (bnd.empty()) return "they have no boundary of their own";
  std::map<int, std::vector<std::size_t>> at;   // vertex -> boundary curves ending there
  for (std::size_t i = 0; i < bnd.size(); ++i) {
    const geo::ModelCurve* mc = m.curve(bnd[i]);
    at[mc->begin].push_back(i);
    at[mc->end].push_back(i);
  }
  for (const auto& [v, ends] : at)
    if (ends.size() != 2) return fmt::format("their boundary is not a set of closed loops at point {}", v);
  // Closed chains; each step uses one more curve, so at most bnd.size() steps in all.
  std::vector<char> used(bnd.size(), 0);
  for (std::size_t i = 0; i < bnd.size(); ++i) {
    if (used[i]) continue;
    std::vector<int> chain;
    const int start = m.curve(bnd[i])->begin;
    int v = start;
    std::size_t cur = i;
    for (std::size_t step = 0; step < bnd.size(); ++step) {
      used[cur] = 1;
      const geo::ModelCurve* mc = m.curve(bnd[cur]);
      const bool forward = mc->begin == v;
      chain.push_back(forward ? mc->tag : -mc->tag);
      v = forward ? mc->end : mc->begin;
      if (v == start) break;
      std::optional<std::size_t> next;
      for (std::size_t j : at.at(v))
        if (!used[j]) next = j;
      if (!next) break;
      cur = *next;
    }
    if (v != start) return "their boundary does not close";
    u.chains.push_back(std::move(chain));
  }
  return {};
}

// The chain whose curves span the largest box: the outer boundary (it holds the others).
std::size_t outer_chain(const geo::Model& m, const std::vector<std::vector<int>>& chains) {
  std::size_t best = 0;
  double best_d = -1;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    geo::BoundingBox box;
    for (int c : chains[i]) {
      const geo::BoundingBox b = m.curve_bounding_box(std::abs(c));
      if (!b.empty()) box.add(b.lo), box.add(b.hi);
    }
    if (box.diagonal() > best_d) best = i, best_d = box.diagonal();
  }
  return best;
}

// Replaces the surfaces `tags` of plan.model by their union; why not, if it cannot.
std::string combine(CompoundSurfacePlan& plan, const geo::Model& model, const std::vector<int>& tags) {
  Union u;
  if (std::string why = check_union(model, tags, u); !why.empty()) return why;
  geo::Model& m = plan.model;
  std::vector<int> loops;
  const std::size_t outer = outer_chain(model, u.chains);
  for (std::size_t i = 0; i < u.chains.size(); ++i) {
    const int tag = m.new_loop_tag();
    if (const geo::GeoStatus st = m.add_curve_loop(tag, u.chains[i]); !st) return geo::summary(st.error());
    if (i == outer) loops.insert(loops.begin(), tag);
    else loops.push_back(tag);
  }
  const int union_tag = m.new_surface_tag();
  std::vector<int> points, curves;
  for (int t : tags) {
    const geo::ModelSurface* s = model.surface(t);
    points.insert(points.end(), s->embedded_points.begin(), s->embedded_points.end());
    curves.insert(curves.end(), s->embedded_curves.begin(), s->embedded_curves.end());
  }
  std::vector<geo::DimTag> originals;
  for (int t : tags) originals.push_back({2, t});
  if (const geo::GeoStatus st = m.remove(originals, false); !st) return geo::summary(st.error());
  if (const geo::GeoStatus st = m.add_plane_surface(union_tag, loops); !st) return geo::summary(st.error());
  for (std::vector<int>* list : {&points, &curves}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  if (!points.empty())
    if (const geo::GeoStatus st = m.embed(0, points, union_tag); !st) return geo::summary(st.error());
  if (!curves.empty())
    if (const geo::GeoStatus st = m.embed(1, curves, union_tag); !st) return geo::summary(st.error());
  (void)m.take_compat_notes();   // the copy's notes: the script's statements made theirs
  plan.groups.push_back({union_tag, tags, u.geometry, u.normal});
  return {};
}

}  // namespace

CompoundSurfacePlan plan_compound_surfaces(const geo::Model& model, const std::vector<std::vector<int>>& groups) {
  CompoundSurfacePlan plan;
  if (groups.empty()) return plan;
  plan.model = model;
  std::set<int> taken;
  for (const std::vector<int>& written : groups) {
    std::vector<int> tags;
    for (int t : written) {
      const int a = std::abs(t);
      if (model.surface(a) && !taken.count(a) && std::find(tags.begin(), tags.end(), a) == tags.end())
        tags.push_back(a);
    }
    if (tags.size() < 2) continue;   // one surface: meshed as it is
    const geo::Model before = plan.model;
    if (std::string why = combine(plan, model, tags); !why.empty()) {
      plan.model = before;   // a half-made union undone
      plan.declined.push_back({tags, std::move(why)});
      continue;
    }
    taken.insert(tags.begin(), tags.end());
  }
  return plan;
}

namespace {

// The segments of a surface's boundary mesh (its loops' curve meshes), in the plane.
std::vector<std::pair<Vec2, Vec2>> boundary_segments(const geo::Model& model, const ModelMesh& mesh, int surface,
                                                     const auto& proj) {
  std::vector<std::pair<Vec2, Vec2>> out;
  const geo::ModelSurface* s = model.surface(surface);
  if (!s) return out;
  for (int l : s->loops) {
    const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l));
    if (!loop) continue;
    for (int c : loop->curves) {
      const auto it = mesh.curves.find(std::abs(c));
      if (it == mesh.curves.end()) continue;
      const std::vector<std::uint32_t>& nodes = it->second.nodes;
      for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
        out.emplace_back(proj(mesh.nodes[nodes[i]]), proj(mesh.nodes[nodes[i + 1]]));
    }
  }
  return out;
}

// Inside (or on) the region the segments bound: the crossing number of the ray to +x.
bool inside(const std::vector<std::pair<Vec2, Vec2>>& segs, Vec2 p) {
  bool in = false;
  for (const auto& [a, b] : segs) {
    const RayCrossing r = ray_crossing(a, b, p);
    if (r == RayCrossing::OnEdge) return true;
    if (r == RayCrossing::Crosses) in = !in;
  }
  return in;
}

}  // namespace

void classify_compound_elements(const geo::Model& model, const CompoundSurfacePlan& plan, ModelMesh& mesh) {
  for (const CompoundSurfacePlan::Group& g : plan.groups) {
    const auto found = mesh.surfaces.find(g.union_tag);
    if (found == mesh.surfaces.end()) continue;
    SurfaceMesh whole = std::move(found->second);
    mesh.surfaces.erase(found);
    // The plane's coordinates: (u, v) on a geometry, else two axes across the normal.
    const Vec3 n = g.normal;
    const Vec3 helper = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 e1 = (1.0 / norm(cross(n, helper))) * cross(n, helper);
    const Vec3 e2 = cross(n, e1);
    const bool on_uv = g.geometry != 0;
    auto proj = [&](const MeshNode& node) { return on_uv ? node.uv : Vec2{dot(node.xyz, e1), dot(node.xyz, e2)}; };
    std::vector<std::vector<std::pair<Vec2, Vec2>>> segs;
    for (int s : g.surfaces) segs.push_back(boundary_segments(model, mesh, s, proj));
    // The first original holding p; the first of all when none does (rounding on a
    // boundary the union's mesh moved).
    auto owner = [&](Vec2 p) {
      for (std::size_t i = 0; i < segs.size(); ++i)
        if (inside(segs[i], p)) return i;
      return std::size_t{0};
    };
    std::vector<SurfaceMesh> parts(g.surfaces.size());
    for (std::size_t i = 0; i < parts.size(); ++i) parts[i].tag = g.surfaces[i];
    for (std::uint32_t v : whole.interior_nodes) parts[owner(proj(mesh.nodes[v]))].interior_nodes.push_back(v);
    for (const auto& t : whole.triangles) {
      const Vec2 c = (1.0 / 3.0) * (proj(mesh.nodes[t[0]]) + proj(mesh.nodes[t[1]]) + proj(mesh.nodes[t[2]]));
      parts[owner(c)].triangles.push_back(t);
    }
    for (const auto& q : whole.quads) {
      const Vec2 c = 0.25 * (proj(mesh.nodes[q[0]]) + proj(mesh.nodes[q[1]]) + proj(mesh.nodes[q[2]]) +
                             proj(mesh.nodes[q[3]]));
      parts[owner(c)].quads.push_back(q);
    }
    for (SurfaceMesh& p : parts) mesh.surfaces[p.tag] = std::move(p);
  }
}

void name_compound_unions(const CompoundSurfacePlan& plan, std::string& text) {
  for (const CompoundSurfacePlan::Group& g : plan.groups) {
    const std::string word = fmt::format("surface {}", g.union_tag);
    // "surface U" only as a whole word: not the start of "surface U0".
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at)) {
      const std::size_t end = at + word.size();
      if (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) {
        at = end;
        continue;
      }
      const std::string by = fmt::format("the union of Compound Surface{{{}}}", tag_list(g.surfaces));
      text.replace(at, word.size(), by);
      at += by.size();
    }
  }
}

const std::vector<int>* compound_union_of(const CompoundSurfacePlan& plan, int surface) {
  for (const CompoundSurfacePlan::Group& g : plan.groups)
    if (g.union_tag == surface) return &g.surfaces;
  return nullptr;
}

void name_compound_unions(const CompoundSurfacePlan& plan, MeshError& error) {
  for (const CompoundSurfacePlan::Group& g : plan.groups)
    for (MeshEntity& e : error.entities)
      if (e.dim == 2 && e.tag == g.union_tag) e.tag = g.surfaces[0];
}

}  // namespace sm
