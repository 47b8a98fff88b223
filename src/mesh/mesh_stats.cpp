// Mesh statistics: quality and size conformity measured on the surface (3D),
// formatted for people and for scripts.
#include "mesh/mesh_stats.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <cmath>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "base/json_text.h"
#include "base/parallel.h"
#include "exact/quality.h"
#include "mesh/recombine.h"
#include "mesh/side_keys.h"

namespace sm {

namespace {

// A length ratio kept as its bits: a ratio is a length over a positive size, >= 0, and
// non-negative doubles (+0 to +inf) order as their bit patterns do as unsigned integers, so
// selection among the bits picks the same order statistics as among the doubles.
double ratio_of(std::uint64_t bits) { return std::bit_cast<double>(bits); }
std::uint64_t bits_of(double ratio) { return std::bit_cast<std::uint64_t>(ratio); }

// The q-quantile of the ratios whose bits are `v` (linear between the two order statistics
// around q (n - 1)), as from the sorted values. Selection instead of a sort: linear in the
// edges, where sorting the 2.9 million of the 3 km world took a tenth of the statistics.
// Only v[lo, hi) is reordered: the caller knows the order statistic is there (those before
// lo no greater, those from hi on no smaller), as after an earlier quantile's selection.
double quantile_in(std::vector<std::uint64_t>& v, std::size_t lo, std::size_t hi, double q) {
  if (v.empty()) return 0;
  const double pos = q * static_cast<double>(v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(i);
  const auto at = v.begin() + static_cast<std::ptrdiff_t>(i);
  std::nth_element(v.begin() + static_cast<std::ptrdiff_t>(lo), at, v.begin() + static_cast<std::ptrdiff_t>(hi));
  if (i + 1 >= v.size()) return ratio_of(*at);
  // The next order statistic: the smallest of those after the i-th in the range, or the
  // first beyond it.
  const double next =
      ratio_of(i + 1 < hi ? *std::min_element(at + 1, v.begin() + static_cast<std::ptrdiff_t>(hi)) : v[hi]);
  return ratio_of(*at) * (1 - f) + next * f;
}

// The median, 5% and 95% quantiles into s: the median first over all the ratios, then the
// others each on its side of it (half the selection work of three over all). When each is
// on its own side they reorder disjoint ranges (the 5% one reads the median's slot past its
// range, which neither writes), so both run at once on `threads` threads; otherwise (a few
// edges) one after the other over all the ratios.
void length_quantiles(std::vector<std::uint64_t>& v, MeshStats& s, int threads) {
  const std::size_t n = v.size();
  const auto index = [n](double q) { return static_cast<std::size_t>(q * static_cast<double>(n - 1)); };
  const std::size_t mid = index(0.5);
  s.len_median = quantile_in(v, 0, n, 0.5);
  const bool below = index(0.05) < mid, above = index(0.95) > mid;
  const std::size_t p05_end = below ? mid : n, p95_begin = above ? mid + 1 : 0;
  parallel_for_chunks(below && above ? threads : 1, 2, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t side = begin; side < end; ++side) {
      if (side == 0) s.len_p05 = quantile_in(v, 0, p05_end, 0.05);
      else s.len_p95 = quantile_in(v, p95_begin, n, 0.95);
    }
  });
}

}  // namespace

namespace {

// The statistics with size_of[k] the target size of the k-th surface in tag order (null:
// none), on `threads` threads (the same figures for any count). Surfaces are measured one
// at a time, so the scratch is one surface's edges: an edge is measured by the first
// surface that holds it; only edges on a surface's border (in one of its triangles) can
// belong to another, so the borders seen so far are kept.
MeshStats compute_stats(const ModelMesh& mesh, const std::vector<const SizeAt3*>& size_of, int threads) {
  MeshStats s;
  // Nodes of the triangles, as a mesh file holds them: the model points that
  // no triangle uses (B-spline control points, a sphere's centre) do not count.
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const auto& [tag, sf] : mesh.surfaces)
  {
    for (const auto& t : sf.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
    for (const auto& q : sf.quads) used[q[0]] = used[q[1]] = used[q[2]] = used[q[3]] = 1;
  }
  s.nodes = static_cast<std::uint64_t>(std::count(used.begin(), used.end(), 1));
  double sum = 0, quad_sum = 0;
  std::uint64_t good = 0, in_range = 0;
  s.min_rho = 1;
  std::vector<EdgeKey> border, seen_border, merged;
  // One array for the edges and their length ratios: the bits of the ratios of the
  // surfaces measured so far (bits_of), then the current surface's edge keys, each
  // replaced by its ratio's bits once measured. Sized once for every side of the sized
  // surfaces, 8 bytes a side: the ratios in an array of their own beside the keys were
  // another 8 bytes an edge at the statistics' peak (the run's, on the largest meshes).
  std::vector<std::uint64_t> slots;
  {
    std::size_t sides = 0, index = 0;
    for (const auto& [tag, sf] : mesh.surfaces)
      if (index < size_of.size() && size_of[index++]) sides += 3 * sf.triangles.size() + 4 * sf.quads.size();
    slots.reserve(sides);
  }
  // The qualities are measured a block of triangles at a time: a slot per triangle of the
  // surface was 8 bytes a triangle at the statistics' peak (the ten-million-triangle run's).
  constexpr std::size_t kBatch = 4096, kRhoChunk = 1 << 14, kRhoBlock = 64 * kRhoChunk;
  std::vector<double> rhos;
  std::size_t index = 0;
  for (const auto& [tag, sf] : mesh.surfaces) {
    const SizeAt3* size = index < size_of.size() ? size_of[index] : nullptr;
    ++index;
    // The qualities on `threads` threads, then summed in triangle order as one thread
    // would (the same mean to the last bit for any count).
    // (A named reference: a lambda may not capture a structured binding before C++20's
    // P1091 in clang 15.)
    const auto& triangles = sf.triangles;
    for (std::size_t first = 0; first < triangles.size(); first += kRhoBlock) {
      const std::size_t count = std::min(kRhoBlock, triangles.size() - first);
      rhos.resize(count);
      parallel_for_chunks(threads, count, kRhoChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
          const auto& t = triangles[first + k];
          rhos[k] = rho(mesh.nodes[t[0]].xyz, mesh.nodes[t[1]].xyz, mesh.nodes[t[2]].xyz);
        }
      });
      for (std::size_t k = 0; k < count; ++k) {
        const auto& t = triangles[first + k];
        const double r = rhos[k];
        sum += r;
        if (r < s.min_rho || s.min_rho_surface == 0) {
          s.min_rho = std::min(s.min_rho, r);
          s.min_rho_surface = tag;
          s.min_rho_at = (mesh.nodes[t[0]].xyz + mesh.nodes[t[1]].xyz + mesh.nodes[t[2]].xyz) / 3.0;
        }
        if (r > 0.9) ++good;
        ++s.triangles;
      }
    }
    for (const auto& q : sf.quads) {
      const double qq =
          quad_quality(mesh.nodes[q[0]].xyz, mesh.nodes[q[1]].xyz, mesh.nodes[q[2]].xyz, mesh.nodes[q[3]].xyz);
      quad_sum += qq;
      s.quad_min = s.quads == 0 ? qq : std::min(s.quad_min, qq);
      ++s.quads;
    }
    if (!size) continue;
    s.has_sizes = true;
    // The sides' keys in ascending order (a counting sort on threads: std::sort of the
    // ten-million-triangle mesh's 28 million sides was a serial second and a half).
    const std::size_t first = slots.size();
    slots.resize(first + side_count(sf));   // within the capacity reserved above
    const std::span<EdgeKey> edges(slots.data() + first, slots.size() - first);
    sorted_side_keys(sf, edges, threads);
    // Edges in one triangle only (the border), then each distinct edge once, less those
    // an earlier surface measured.
    border.clear();
    std::size_t w = 0;
    for (std::size_t r = 0; r < edges.size();) {
      std::size_t q = r + 1;
      while (q < edges.size() && edges[q] == edges[r]) ++q;
      if (q - r == 1) border.push_back(edges[r]);
      if (!std::binary_search(seen_border.begin(), seen_border.end(), edges[r])) edges[w++] = edges[r];
      r = q;
    }
    slots.resize(first + w);
    const std::span<EdgeKey> distinct(slots.data() + first, w);
    merged.resize(seen_border.size() + border.size());
    std::merge(seen_border.begin(), seen_border.end(), border.begin(), border.end(), merged.begin());
    merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
    seen_border.swap(merged);
    // The sizes at the midpoints in batches of fixed bounds on `threads` threads (the size
    // function is thread-safe, Mesh2dResult::target_sizes), each ratio in its edge's slot
    // (a batch reads its keys before it writes its ratios, and no other batch reads them).
    const std::size_t batches = (w + kBatch - 1) / kBatch;
    std::vector<std::uint64_t> batch_in_range(batches, 0);
    parallel_for_chunks(threads, w, kBatch, [&](std::size_t begin, std::size_t end) {
      std::vector<Vec3> mid(end - begin);
      std::vector<double> h(end - begin), len(end - begin);
      for (std::size_t k = begin; k < end; ++k) {
        const Vec3 a = mesh.nodes[smaller_node(distinct[k])].xyz, b = mesh.nodes[larger_node(distinct[k])].xyz;
        mid[k - begin] = 0.5 * (a + b);
        len[k - begin] = norm(a - b);
      }
      (*size)(mid, h);
      std::uint64_t in = 0;
      for (std::size_t k = begin; k < end; ++k) {
        const double r = len[k - begin] / h[k - begin];
        distinct[k] = bits_of(r);
        if (r >= 0.7 && r <= 1.4) ++in;
      }
      batch_in_range[begin / kBatch] = in;
    });
    for (std::uint64_t in : batch_in_range) in_range += in;
  }
  if (s.quads > 0) s.quad_mean = quad_sum / static_cast<double>(s.quads);
  if (s.triangles == 0 && s.quads == 0) {
    s.min_rho = 0;
    s.has_sizes = false;
    return s;
  }
  if (s.triangles == 0) {
    s.min_rho = 0;
  } else {
    s.mean_rho = sum / static_cast<double>(s.triangles);
    s.share_rho_09 = static_cast<double>(good) / static_cast<double>(s.triangles);
  }
  if (!s.has_sizes) return s;
  s.edges = slots.size();   // every slot holds a ratio now
  if (slots.empty()) return s;
  s.share_len_07_14 = static_cast<double>(in_range) / static_cast<double>(slots.size());
  length_quantiles(slots, s, threads);
  return s;
}

}  // namespace

MeshStats mesh_stats(const ModelMesh& mesh, const SizeAt3& size) {
  return compute_stats(mesh, std::vector<const SizeAt3*>(mesh.surfaces.size(), size ? &size : nullptr), 1);
}

MeshStats mesh_stats(const ModelMesh& mesh, const std::vector<SurfaceSize>& sizes, int threads) {
  std::map<int, const SizeAt3*> by_tag;
  for (const SurfaceSize& ss : sizes)
    if (ss.size) by_tag.emplace(ss.surface, &ss.size);
  std::vector<const SizeAt3*> size_of;
  for (const auto& [tag, sf] : mesh.surfaces) {
    const auto it = by_tag.find(tag);
    size_of.push_back(it == by_tag.end() ? nullptr : it->second);
  }
  return compute_stats(mesh, size_of, resolve_thread_count(threads));
}

std::string format_stats(const MeshStats& s) {
  std::string out = fmt::format("Mesh: {} nodes, {} triangles", s.nodes, s.triangles);
  out += s.quads ? fmt::format(", {} quadrangles\n", s.quads) : std::string("\n");
  std::string worst;
  if (s.min_rho_surface && s.has_min_rho_lonlat)
    worst = fmt::format(" (surface {} near lon {:.4f}, lat {:.4f})", s.min_rho_surface, s.min_rho_lon, s.min_rho_lat);
  else if (s.min_rho_surface)
    worst = fmt::format(" (surface {} near ({:.6g}, {:.6g}, {:.6g}))", s.min_rho_surface, s.min_rho_at.x,
                        s.min_rho_at.y, s.min_rho_at.z);
  if (s.triangles || !s.quads)
    out += fmt::format("Quality: rho min {:.4f}{}, mean {:.4f}, {:.2f}% above 0.9\n", s.min_rho, worst, s.mean_rho,
                       100 * s.share_rho_09);
  if (s.quads)
    out += fmt::format("Quadrangles: corner quality (1 - max |90 - angle| / 90) min {:.4f}, mean {:.4f}\n",
                       s.quad_min, s.quad_mean);
  if (s.has_sizes)
    out += fmt::format("Edge length / size: median {:.3f}, 5-95% [{:.3f}, {:.3f}], {:.2f}% in [0.7, 1.4] ({} edges)\n",
                       s.len_median, s.len_p05, s.len_p95, 100 * s.share_len_07_14, s.edges);
  if (s.partitions > 0)
    out += fmt::format("Partitions: {} (METIS), {} to {} elements, imbalance {:.4f}, edge cut {}\n", s.partitions,
                       s.partition_min, s.partition_max, s.partition_imbalance, s.partition_edge_cut);
  if (s.time_step.valid) {
    const TimeStep& t = s.time_step;
    out += fmt::format("Time step (Courant 1): dt {:.4g} s", t.dt);
    if (t.has_lonlat) out += fmt::format(" at lon {:.4f}, lat {:.4f}", t.lon, t.lat);
    out += fmt::format(" (surface {}, edge {:.4g} m, depth {:.4g} m); 1% of triangles under {:.4g} s\n", t.surface,
                       t.edge, t.depth, t.q01);
  }
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

using base::json_number;
using base::json_string;

std::string stats_json(const MeshStats& s) {
  std::string out = "{";
  out += fmt::format("\"nodes\": {}, \"triangles\": {}, ", s.nodes, s.triangles);
  out += fmt::format("\"rho_min\": {}, \"rho_mean\": {}, \"rho_share_above_0.9\": {}", json_number(s.min_rho),
                     json_number(s.mean_rho), json_number(s.share_rho_09));
  if (s.min_rho_surface) {
    out += fmt::format(", \"rho_min_surface\": {}, \"rho_min_xyz\": [{}, {}, {}]", s.min_rho_surface,
                       json_number(s.min_rho_at.x), json_number(s.min_rho_at.y), json_number(s.min_rho_at.z));
    if (s.has_min_rho_lonlat)
      out += fmt::format(", \"rho_min_lon\": {}, \"rho_min_lat\": {}", json_number(s.min_rho_lon),
                         json_number(s.min_rho_lat));
  }
  if (s.quads)
    out += fmt::format(", \"quadrangles\": {}, \"quad_quality_min\": {}, \"quad_quality_mean\": {}", s.quads,
                       json_number(s.quad_min), json_number(s.quad_mean));
  if (s.has_sizes)
    out += fmt::format(", \"edges\": {}, \"length_ratio_median\": {}, \"length_ratio_p05\": {}, "
                       "\"length_ratio_p95\": {}, \"length_ratio_share_0.7_1.4\": {}",
                       s.edges, json_number(s.len_median), json_number(s.len_p05), json_number(s.len_p95),
                       json_number(s.share_len_07_14));
  if (s.time_step.valid) {
    const TimeStep& t = s.time_step;
    out += fmt::format(", \"dt\": {}, \"dt_edge\": {}, \"dt_depth\": {}, \"dt_surface\": {}", json_number(t.dt),
                       json_number(t.edge), json_number(t.depth), t.surface);
    if (t.has_lonlat) out += fmt::format(", \"dt_lon\": {}, \"dt_lat\": {}", json_number(t.lon), json_number(t.lat));
    out += fmt::format(", \"dt_q01\": {}", json_number(t.q01));
  }
  if (s.has_depth_clamp) {
    const field::DepthClampReport& d = s.depth_clamp;
    out += fmt::format(", \"depth_min\": {}, \"depth_clamped_nodes\": {}, \"depth_clamped_dry\": {}",
                       json_number(d.min_depth), d.clamped, d.dry);
    if (d.has_worst)
      out += fmt::format(", \"depth_clamp_lon\": {}, \"depth_clamp_lat\": {}, \"depth_clamp_grid\": {}, "
                         "\"depth_clamp_value\": {}",
                         json_number(d.lon), json_number(d.lat), json_number(d.grid_depth), json_number(d.value));
  }
  if (s.partitions > 0)
    out += fmt::format(", \"partitions\": {}, \"partition_edge_cut\": {}, \"partition_imbalance\": {}, "
                       "\"partition_min\": {}, \"partition_max\": {}",
                       s.partitions, s.partition_edge_cut, json_number(s.partition_imbalance), s.partition_min,
                       s.partition_max);
  out += ", \"stages\": {";
  for (std::size_t i = 0; i < s.stages.size(); ++i)
    out += fmt::format("{}{}: {}", i ? ", " : "", json_string(s.stages[i].name), json_number(s.stages[i].seconds));
  out += "}";
  if (!s.stages_cpu.empty()) {
    out += ", \"stages_cpu\": {";
    for (std::size_t i = 0; i < s.stages_cpu.size(); ++i)
      out += fmt::format("{}{}: {}", i ? ", " : "", json_string(s.stages_cpu[i].name),
                         json_number(s.stages_cpu[i].seconds));
    out += "}";
  }
  out += "}\n";
  return out;
}

CurveStats curve_stats(const ModelMesh& mesh, Vec3 centre, double radius) {
  CurveStats s;
  std::vector<char> on_curve(mesh.nodes.size(), 0);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double chord_lo = kInf, chord_hi = 0, arc_lo = kInf, arc_hi = 0;
  // A node is on the sphere when its distance from the centre is the radius to within
  // what the projection's round-off leaves (relative 1e-9).
  auto on_sphere = [&](Vec3 p) { return std::abs(norm(p - centre) - radius) <= 1e-9 * radius; };
  bool all_on_sphere = radius > 0;
  for (const auto& [tag, c] : mesh.curves) {
    if (c.num_edges() == 0) continue;
    ++s.curves;
    s.edges += c.num_edges();
    for (std::uint32_t v : c.nodes) s.nodes += on_curve[v] ? 0 : 1, on_curve[v] = 1;
    for (std::size_t i = 0; i + 1 < c.nodes.size(); ++i) {
      const Vec3 a = mesh.nodes[c.nodes[i]].xyz, b = mesh.nodes[c.nodes[i + 1]].xyz;
      const double chord = norm(b - a);
      chord_lo = std::min(chord_lo, chord);
      chord_hi = std::max(chord_hi, chord);
      all_on_sphere = all_on_sphere && on_sphere(a) && on_sphere(b);
      if (!all_on_sphere) continue;
      const double arc = 2 * radius * std::asin(std::min(1.0, chord / (2 * radius)));
      arc_lo = std::min(arc_lo, arc);
      arc_hi = std::max(arc_hi, arc);
    }
  }
  if (s.edges == 0) return s;
  // One edge off the sphere (a mixed model): chords for all, so that the figures compare.
  s.on_sphere = all_on_sphere;
  s.shortest = s.on_sphere ? arc_lo : chord_lo;
  s.longest = s.on_sphere ? arc_hi : chord_hi;
  return s;
}

std::string format_curve_stats(const CurveStats& s) {
  const std::string counts = fmt::format("Mesh: {} nodes, {} line elements on {} curve{}", s.nodes, s.edges, s.curves,
                                         s.curves == 1 ? "" : "s");
  if (s.on_sphere)
    return fmt::format("{}; edges from {:.4g} km to {:.4g} km on the sphere\n", counts, s.shortest / 1000,
                       s.longest / 1000);
  return fmt::format("{}; edges from {:.6g} to {:.6g} (model units)\n", counts, s.shortest, s.longest);
}

std::string curve_stats_json(const CurveStats& s, const std::vector<StageTime>& stages) {
  std::string out = fmt::format("{{\"nodes\": {}, \"line_elements\": {}, \"curves\": {}, \"edge_min\": {}, "
                                "\"edge_max\": {}, \"edge_units\": {}",
                                s.nodes, s.edges, s.curves, json_number(s.shortest), json_number(s.longest),
                                json_string(s.on_sphere ? "m" : "model"));
  out += ", \"stages\": {";
  for (std::size_t i = 0; i < stages.size(); ++i)
    out += fmt::format("{}{}: {}", i ? ", " : "", json_string(stages[i].name), json_number(stages[i].seconds));
  out += "}}\n";
  return out;
}

}  // namespace sm
