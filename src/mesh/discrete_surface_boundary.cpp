// Boundary edges of a discrete surface, matched against its discrete curves' mesh edges.
#include "mesh/discrete_surface_boundary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace sm {

namespace {

using NodeEdge = std::pair<std::uint64_t, std::uint64_t>;   // smaller tag first

NodeEdge node_edge(std::uint64_t a, std::uint64_t b) { return a < b ? NodeEdge{a, b} : NodeEdge{b, a}; }

// How many of the surface's elements use each edge.
std::map<NodeEdge, int> edge_uses(const DiscreteSurface& s) {
  std::map<NodeEdge, int> uses;
  for (const auto& t : s.triangles)
    for (int e = 0; e < 3; ++e) ++uses[node_edge(t[e], t[(e + 1) % 3])];
  for (const auto& q : s.quads)
    for (int e = 0; e < 4; ++e) ++uses[node_edge(q[e], q[(e + 1) % 4])];
  return uses;
}

// The largest distance of a node of `s` from the plane through their centroid normal to
// the sum of the elements' area vectors; `worst` gets that node.
double off_plane(const DiscreteEntities& d, const DiscreteSurface& s, std::uint64_t& worst, double& diag) {
  std::vector<std::uint64_t> nodes;
  for (const auto& t : s.triangles) nodes.insert(nodes.end(), t.begin(), t.end());
  for (const auto& q : s.quads) nodes.insert(nodes.end(), q.begin(), q.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  Vec3 normal{0, 0, 0}, centre{0, 0, 0}, lo = d.nodes.at(nodes[0]), hi = lo;
  const auto add_area = [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    normal = normal + cross(d.nodes.at(b) - d.nodes.at(a), d.nodes.at(c) - d.nodes.at(a));
  };
  for (const auto& t : s.triangles) add_area(t[0], t[1], t[2]);
  for (const auto& q : s.quads) add_area(q[0], q[1], q[2]), add_area(q[0], q[2], q[3]);
  for (std::uint64_t v : nodes) {
    const Vec3 p = d.nodes.at(v);
    centre = centre + p;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  centre = centre * (1.0 / static_cast<double>(nodes.size()));
  diag = norm(hi - lo);
  const double n = norm(normal);
  worst = nodes[0];
  if (!(n > 0)) return diag;   // a closed surface: its area vectors cancel
  double far = 0;
  for (std::uint64_t v : nodes) {
    const double h = std::abs(dot(d.nodes.at(v) - centre, normal)) / n;
    if (h > far) far = h, worst = v;
  }
  return far;
}

// The curves grouped by the chains their end nodes join (union-find on the end nodes).
std::vector<std::vector<int>> chains_of(const DiscreteEntities& d, const std::vector<int>& curves) {
  std::map<std::uint64_t, std::uint64_t> parent;
  const auto root = [&parent](std::uint64_t v) {
    // Paths are halved on the way: each step moves up one level of a finite forest.
    while (parent.at(v) != v) v = parent[v] = parent.at(parent.at(v));
    return v;
  };
  for (int c : curves)
    for (std::uint64_t v : {d.curve_nodes.at(c).front(), d.curve_nodes.at(c).back()}) parent.emplace(v, v);
  for (int c : curves) {
    const std::uint64_t a = root(d.curve_nodes.at(c).front()), b = root(d.curve_nodes.at(c).back());
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  std::map<std::uint64_t, std::vector<int>> by_root;
  for (int c : curves) by_root[root(d.curve_nodes.at(c).front())].push_back(c);
  std::vector<std::vector<int>> out;
  for (auto& [r, cs] : by_root) out.push_back(std::move(cs));
  return out;
}

// The bounding-box diagonal of a chain's nodes: the enclosing chain reaches farthest.
double reach(const DiscreteEntities& d, const std::vector<int>& chain) {
  Vec3 lo = d.nodes.at(d.curve_nodes.at(chain[0]).front()), hi = lo;
  for (int c : chain)
    for (std::uint64_t v : d.curve_nodes.at(c)) {
      const Vec3 p = d.nodes.at(v);
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return norm(hi - lo);
}

}  // namespace

DiscreteSurfaceBoundary discrete_surface_boundary(const DiscreteEntities& d, int surface,
                                                  const std::vector<int>& curves) {
  DiscreteSurfaceBoundary out;
  const DiscreteSurface& s = d.surfaces.at(surface);
  double diag = 0;
  out.distance = off_plane(d, s, out.node_a, diag);
  if (out.distance > 1e-6 * diag) {
    out.problem = DiscreteSurfaceBoundary::Problem::NotPlanar;
    return out;
  }
  std::map<NodeEdge, int> uses = edge_uses(s);
  std::vector<int> bounding;
  for (int c : curves) {
    const std::vector<std::uint64_t>& nodes = d.curve_nodes.at(c);
    std::size_t on_boundary = 0, inside = 0;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
      const auto it = uses.find(node_edge(nodes[i], nodes[i + 1]));
      if (it == uses.end()) continue;
      (it->second == 1 ? on_boundary : inside) += 1;
    }
    const std::size_t edges = nodes.size() - 1;
    if (on_boundary == edges) bounding.push_back(c);
    else if (inside == edges) out.inner_curves.push_back(c);
    else if (on_boundary + inside > 0) {
      out.problem = DiscreteSurfaceBoundary::Problem::CurvePartlyIn;
      out.curve = c;
      return out;
    }
  }
  for (int c : bounding) {
    const std::vector<std::uint64_t>& nodes = d.curve_nodes.at(c);
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) uses.at(node_edge(nodes[i], nodes[i + 1])) = 0;
  }
  for (const auto& [e, n] : uses)
    if (n == 1) {
      out.problem = DiscreteSurfaceBoundary::Problem::EdgeOnNoCurve;
      out.node_a = e.first, out.node_b = e.second;
      return out;
    }
  out.loops = chains_of(d, bounding);
  // Stable: equal reaches keep the chains' order (by their smallest end node).
  std::stable_sort(out.loops.begin(), out.loops.end(), [&d](const std::vector<int>& a, const std::vector<int>& b) {
    return reach(d, a) > reach(d, b);
  });
  return out;
}

}  // namespace sm
