// Mesh statistics of issue 7: quality and size conformity measured on the surface (3D),
// formatted for people and for scripts.
#include "mesh/mesh_stats.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace sm {

double rho3(Vec3 a, Vec3 b, Vec3 c) {
  const double la = norm(b - c), lb = norm(c - a), lc = norm(a - b);
  const double area2 = norm2(cross(b - a, c - a));  // (2A)^2
  const double den = (la + lb + lc) * la * lb * lc;
  return den > 0 ? 4 * area2 / den : 0.0;
}

namespace {

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  const double pos = q * static_cast<double>(sorted.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(i);
  return i + 1 < sorted.size() ? sorted[i] * (1 - f) + sorted[i + 1] * f : sorted[i];
}

}  // namespace

MeshStats mesh_stats(const ModelMesh& mesh, const SizeAt3& size) {
  MeshStats s;
  // Nodes of the triangles, as a mesh file holds them: the model points that
  // no triangle uses (B-spline control points, a sphere's centre) do not count.
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const auto& [tag, sf] : mesh.surfaces)
    for (const auto& t : sf.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  s.nodes = static_cast<std::uint64_t>(std::count(used.begin(), used.end(), 1));
  double sum = 0;
  std::uint64_t good = 0;
  s.min_rho = 1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& [tag, sf] : mesh.surfaces) {
    for (const auto& t : sf.triangles) {
      const double r = rho3(mesh.nodes[t[0]].xyz, mesh.nodes[t[1]].xyz, mesh.nodes[t[2]].xyz);
      sum += r;
      s.min_rho = std::min(s.min_rho, r);
      if (r > 0.9) ++good;
      ++s.triangles;
      if (size)
        for (int e = 0; e < 3; ++e) edges.push_back(std::minmax(t[e], t[(e + 1) % 3]));
    }
  }
  if (s.triangles == 0) {
    s.min_rho = 0;
    return s;
  }
  s.mean_rho = sum / static_cast<double>(s.triangles);
  s.share_rho_09 = static_cast<double>(good) / static_cast<double>(s.triangles);
  if (!size) return s;
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  s.edges = edges.size();
  s.has_sizes = true;
  std::vector<double> ratio(edges.size());
  constexpr std::size_t kBatch = 4096;
  std::vector<Vec3> mid;
  std::vector<double> h;
  std::uint64_t in_range = 0;
  for (std::size_t i = 0; i < edges.size(); i += kBatch) {
    const std::size_t n = std::min(kBatch, edges.size() - i);
    mid.resize(n);
    h.resize(n);
    for (std::size_t k = 0; k < n; ++k)
      mid[k] = 0.5 * (mesh.nodes[edges[i + k].first].xyz + mesh.nodes[edges[i + k].second].xyz);
    size(mid, h);
    for (std::size_t k = 0; k < n; ++k) {
      const double len = norm(mesh.nodes[edges[i + k].first].xyz - mesh.nodes[edges[i + k].second].xyz);
      ratio[i + k] = len / h[k];
      if (ratio[i + k] >= 0.7 && ratio[i + k] <= 1.4) ++in_range;
    }
  }
  s.share_len_07_14 = static_cast<double>(in_range) / static_cast<double>(edges.size());
  std::sort(ratio.begin(), ratio.end());
  s.len_median = quantile(ratio, 0.5);
  s.len_p05 = quantile(ratio, 0.05);
  s.len_p95 = quantile(ratio, 0.95);
  return s;
}

std::string format_stats(const MeshStats& s) {
  std::string out = fmt::format("Mesh: {} nodes, {} triangles\n", s.nodes, s.triangles);
  out += fmt::format("Quality: rho min {:.4f}, mean {:.4f}, {:.2f}% above 0.9\n", s.min_rho, s.mean_rho,
                     100 * s.share_rho_09);
  if (s.has_sizes)
    out += fmt::format("Edge length / size: median {:.3f}, 5-95% [{:.3f}, {:.3f}], {:.2f}% in [0.7, 1.4] ({} edges)\n",
                       s.len_median, s.len_p05, s.len_p95, 100 * s.share_len_07_14, s.edges);
  if (!s.stages.empty()) {
    out += "Time:";
    double total = 0;
    for (const StageTime& st : s.stages) {
      out += fmt::format(" {} {:.3f} s,", st.name, st.seconds);
      total += st.seconds;
    }
    out += fmt::format(" total {:.3f} s\n", total);
  }
  return out;
}

namespace {

std::string json_string(const std::string& in) {
  std::string out = "\"";
  for (char c : in) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
    else out += c;
  }
  return out + "\"";
}

// Finite numbers as the shortest round-trip text; JSON has no NaN or infinity.
std::string json_number(double v) { return std::isfinite(v) ? fmt::format("{}", v) : "null"; }

}  // namespace

std::string stats_json(const MeshStats& s) {
  std::string out = "{";
  out += fmt::format("\"nodes\": {}, \"triangles\": {}, ", s.nodes, s.triangles);
  out += fmt::format("\"rho_min\": {}, \"rho_mean\": {}, \"rho_share_above_0.9\": {}", json_number(s.min_rho),
                     json_number(s.mean_rho), json_number(s.share_rho_09));
  if (s.has_sizes)
    out += fmt::format(", \"edges\": {}, \"length_ratio_median\": {}, \"length_ratio_p05\": {}, "
                       "\"length_ratio_p95\": {}, \"length_ratio_share_0.7_1.4\": {}",
                       s.edges, json_number(s.len_median), json_number(s.len_p05), json_number(s.len_p95),
                       json_number(s.share_len_07_14));
  out += ", \"stages\": {";
  for (std::size_t i = 0; i < s.stages.size(); ++i)
    out += fmt::format("{}{}: {}", i ? ", " : "", json_string(s.stages[i].name), json_number(s.stages[i].seconds));
  out += "}}\n";
  return out;
}

}  // namespace sm
