// refine_partitioned: coarse pass, bisection, border subdivision, per-part CDT + refinement
// through parallel_for_chunks (one part per chunk), merge with cross-part twins matched by
// sorting the parts' hull edges. Nothing here depends on the thread count.
#include "mesh/partition.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "base/elapsed.h"
#include "base/parallel.h"
#include "base/release_memory.h"
#include "mesh/cdt.h"
#include "mesh/delaunay.h"
#include "mesh/frontal.h"

namespace sm {
namespace {

constexpr double kEquilateralArea = 0.4330127018922193;  // sqrt(3)/4: equilateral of side 1
constexpr std::size_t kBatch = 4096;
// Points a chunk of a large batch of sizes on the threads (sizes_in_chunks).
constexpr std::size_t kSizeChunk = 1024;

// h[i] = the size at p[i] in chunks of kSizeChunk points on up to `threads` threads, each
// chunk by an evaluator of its own (PartitionOptions::sizes_by_point).
void sizes_in_chunks(std::span<const Vec2> p, std::span<double> h, const std::function<PlaneSizeFn()>& make_size,
                     int threads) {
  parallel_for_chunks(threads, p.size(), kSizeChunk, [&](std::size_t b, std::size_t e) {
    make_size()(p.subspan(b, e - b), h.subspan(b, e - b));
  });
}

double area(const TriangleStore& m, std::uint32_t t) {
  const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

std::vector<std::uint32_t> live_triangles(const TriangleStore& m) {
  std::vector<std::uint32_t> t;
  t.reserve(m.num_triangles());
  for (std::uint32_t i = 0; i < m.num_slots(); ++i)
    if (m.alive(TriId{i})) t.push_back(i);
  return t;
}

// One batch of estimate_each: items [b, e) of tris.
void estimate_batch(const TriangleStore& m, std::span<const std::uint32_t> tris, std::size_t b, std::size_t e,
                    const PlaneSizeFn& size, std::vector<Vec2>& mid, std::vector<double>& h, std::vector<Vec2>& c,
                    std::vector<double>& w) {
  const std::size_t n = e - b;
  mid.resize(3 * n);
  h.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const TriId t{tris[b + i]};
    const Vec2 p[3] = {m.pos(m.vertex(t, 0)), m.pos(m.vertex(t, 1)), m.pos(m.vertex(t, 2))};
    c[b + i] = (p[0] + p[1] + p[2]) / 3.0;
    for (int k = 0; k < 3; ++k) mid[3 * i + k] = 0.5 * (p[k] + p[(k + 1) % 3]);
  }
  size(mid, h);
  for (std::size_t i = 0; i < n; ++i) {
    double inv = 0;
    for (int k = 0; k < 3; ++k) {
      const double x = h[3 * i + k];
      if (x > 0 && std::isfinite(x)) inv += 1 / (3 * x * x);
    }
    w[b + i] = area(m, tris[b + i]) * inv / kEquilateralArea;
  }
}

// Centroids and estimated final triangle counts of the listed triangles: the area times
// the mean of 1/(equilateral area at the size) at the three edge midpoints (a rule exact
// for quadratics: the size varies across the large coarse triangles, and 1/h^2 is convex
// in it, so the centroid alone underestimated the world ocean by 40%). A non-positive or
// non-finite size counts 0 (the refiner reports it). In batches of kBatch triangles: with
// make_size and more than one thread, the batches run on the threads, each sized by an
// evaluator of its own (for a size that depends on the point alone: the same weights);
// otherwise in turn, by `size` (or, when null, one evaluator from make_size).
void estimate_each(const TriangleStore& m, std::span<const std::uint32_t> tris, const PlaneSizeFn& size,
                   std::vector<Vec2>& c, std::vector<double>& w,
                   const std::function<PlaneSizeFn()>& make_size = nullptr, int threads = 1) {
  c.resize(tris.size());
  w.assign(tris.size(), 0.0);
  if (make_size && threads > 1 && tris.size() > kBatch) {
    parallel_for_chunks(threads, tris.size(), kBatch, [&](std::size_t b, std::size_t e) {
      std::vector<Vec2> mid;
      std::vector<double> h;
      estimate_batch(m, tris, b, e, make_size(), mid, h, c, w);
    });
    return;
  }
  const PlaneSizeFn serial = size ? size : make_size();
  std::vector<Vec2> mid;
  std::vector<double> h;
  for (std::size_t b = 0; b < tris.size(); b += kBatch)
    estimate_batch(m, tris, b, std::min(tris.size(), b + kBatch), serial, mid, h, c, w);
}

void add_stats(RefineStats& to, const RefineStats& s) {
  to.inserted += s.inserted;
  to.rejected += s.rejected;
  to.pops += s.pops;
  to.stale += s.stale;
  to.walk_steps += s.walk_steps;
  to.cavity_triangles += s.cavity_triangles;
}

// A coarse edge between two parts, subdivided: points [first, first + count) of the
// border point array, ordered from a to b (a < b).
struct Border {
  VertexId a, b;
  std::uint32_t first = 0, count = 0;
};

// The coarse mesh and its cut, read (never written) by every part.
struct Coarse {
  TriangleStore m;
  std::vector<std::uint32_t> part_of;         // per slot
  std::vector<std::vector<std::uint32_t>> part_tris;
  std::vector<std::uint32_t> border_of_side;  // per side: index into borders, or kNoIndex
  std::vector<Border> borders;
  std::vector<Vec2> border_xy;
  // Per coarse vertex: its id in the result, kNoIndex for a vertex inside a part (dropped:
  // a part is refined from its boundary alone, so fronts meet no stray vertex). The input
  // vertices keep their ids; border vertices follow in coarse id order, then border points.
  std::vector<std::uint32_t> new_id;
  std::uint32_t n_kept = 0;
};

// One part after refinement: its compacted store and the merged id of each of its first
// n_init vertices (kept coarse vertices, then border points).
struct PartOut {
  TriangleStore st;
  std::vector<std::uint32_t> global_of;
  std::uint32_t n_init = 0;
  RefineStats stats;
  std::string error;
};

// A finished part waits for the merge: it keeps only its live data, and the refinement's
// scratch (queue, sizes, cavities) and the arrays shrink_to_fit replaced, freed among the
// parts still waiting, are given back, or the resident memory of the part phase is that of
// every part's peak (the world at 10 km: 49 MiB resident for 23 MiB of parts).
void keep_for_merge(TriangleStore& P) {
  P.corner.shrink_to_fit();
  P.twin.shrink_to_fit();
  P.side_flags.shrink_to_fit();
  P.tri_flags.shrink_to_fit();
  P.xy.shrink_to_fit();
  P.out_side = {};
  P.free_tris = {};
  release_free_memory();
}

// Triangulates part p (its kept coarse vertices and border points, its constrained edges
// and the border sub-edges recovered, the outside removed by a flood fill from the part's
// side of its boundary) and refines it.
void mesh_part(const Coarse& c, std::uint32_t p, const RefineOptions& base, PartRefiner kind,
               const PlaneSizeFn& size, PartOut& out) {
  const std::vector<std::uint32_t>& tris = c.part_tris[p];
  if (tris.empty()) return;
  const TriangleStore& cm = c.m;
  // The part's vertices: its kept coarse vertices (coarse id order), then border points.
  std::vector<std::uint32_t> cv;
  for (std::uint32_t t : tris)
    for (std::uint32_t e = 0; e < 3; ++e)
      if (c.new_id[cm.vertex(TriId{t}, e).value] != kNoIndex) cv.push_back(cm.vertex(TriId{t}, e).value);
  std::sort(cv.begin(), cv.end());
  cv.erase(std::unique(cv.begin(), cv.end()), cv.end());
  auto local = [&](VertexId v) {
    return VertexId{static_cast<std::uint32_t>(std::lower_bound(cv.begin(), cv.end(), v.value) - cv.begin())};
  };
  TriangleStore& P = out.st;
  std::vector<std::uint32_t>& g = out.global_of;
  for (std::uint32_t v : cv) {
    P.add_vertex(cm.pos(VertexId{v}));
    g.push_back(c.new_id[v]);
  }

  std::vector<Edge> edges;     // to recover
  std::vector<Edge> bounds;    // the part's boundary, the part on the left
  std::vector<Edge> subs;      // border sub-edges: unconstrained after refinement
  std::vector<std::pair<Edge, std::uint8_t>> flagged;  // coarse constrained edges and their flags
  std::vector<VertexId> chain;
  for (std::uint32_t t : tris)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s = side_of(TriId{t}, e);
      const Side o = cm.twin[s.value];
      const bool outer = !o.valid() || c.part_of[tri_of(o).value] != p;
      const VertexId a = cm.org(s), b = cm.dest(s);
      if (cm.constrained(s)) {
        if (!outer && a.value > b.value) continue;  // the twin in this part adds it
        edges.push_back({local(a), local(b)});
        flagged.push_back({edges.back(), cm.side_flags[s.value]});
        if (outer) bounds.push_back(edges.back());
        continue;
      }
      if (!outer) continue;
      const Border& br = c.borders[c.border_of_side[s.value]];
      // The border's points get local ids here: each border has one side in this part.
      const std::uint32_t first = P.num_vertices();
      for (std::uint32_t k = 0; k < br.count; ++k) {
        P.add_vertex(c.border_xy[br.first + k]);
        g.push_back(c.n_kept + br.first + k);
      }
      chain.assign(1, local(a));
      for (std::uint32_t k = 0; k < br.count; ++k)
        chain.push_back(VertexId{a == br.a ? first + k : first + br.count - 1 - k});
      chain.push_back(local(b));
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
        edges.push_back({chain[k], chain[k + 1]});
        bounds.push_back(edges.back());
        subs.push_back(edges.back());
      }
    }
  out.n_init = P.num_vertices();

  const DelaunayResult dr = delaunay(P);
  if (!dr.ok()) {
    out.error = "Delaunay failed: " + dr.error;
    return;
  }
  if (!dr.duplicates.empty()) {
    const Vec2 x = P.pos(dr.duplicates[0].dup);
    out.error = fmt::format("two points at the same place ({}, {})", x.x, x.y);
    return;
  }
  const PlanarGeometry geom{&P.xy};
  const RecoverResult rr = recover_edges(P, geom, edges);
  if (!rr.clean()) {
    out.error = rr.ok() ? "a border or boundary edge could not be recovered" : "edge recovery failed: " + rr.error;
    return;
  }

  // Flood fill from the part's side of its boundary; the boundary stops it.
  std::vector<std::uint8_t> stop(P.corner.size(), 0), inside(P.num_slots(), 0);
  std::vector<std::uint32_t> stack;
  for (const Edge& e : bounds) {
    const Side s = P.side_between(e.first, e.second);
    if (!s.valid()) {
      out.error = "a part boundary edge is missing after recovery";
      return;
    }
    stop[s.value] = 1;
    if (P.twin[s.value].valid()) stop[P.twin[s.value].value] = 1;
  }
  for (const Edge& e : bounds) {
    const std::uint32_t t = tri_of(P.side_between(e.first, e.second)).value;
    if (!inside[t]) inside[t] = 1, stack.push_back(t);
  }
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s = side_of(TriId{t}, e);
      if (stop[s.value]) continue;
      const Side o = P.twin[s.value];
      if (!o.valid()) {
        out.error = "the part's boundary is not closed";
        return;
      }
      if (!inside[tri_of(o).value]) inside[tri_of(o).value] = 1, stack.push_back(tri_of(o).value);
    }
  }
  for (std::uint32_t t = 0; t < inside.size(); ++t)
    if (!inside[t] && P.alive(TriId{t})) P.kill_triangle(TriId{t});
  P.rebuild_out_side();
  // A part may touch itself at a vertex (two fans there), where side_between cannot see
  // every edge: edges are looked up by their vertex pair over all sides instead.
  auto key = [](VertexId a, VertexId b) {
    return std::pair<std::uint32_t, std::uint32_t>(std::min(a.value, b.value), std::max(a.value, b.value));
  };
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::uint8_t>> flag_of;
  for (const auto& [e, f] : flagged) flag_of.push_back({key(e.first, e.second), f});
  std::sort(flag_of.begin(), flag_of.end());
  for (std::uint32_t s = 0; s < P.corner.size(); ++s) {
    if (!P.constrained(Side{s}) || !P.alive(tri_of(Side{s}))) continue;
    const auto k = key(P.org(Side{s}), P.dest(Side{s}));
    const auto it = std::lower_bound(flag_of.begin(), flag_of.end(), std::make_pair(k, std::uint8_t{0}));
    if (it != flag_of.end() && it->first == k) P.side_flags[s] |= it->second;
  }

  RefineOptions ro = base;
  ro.size_at = size;
  const RefineResult r = kind == PartRefiner::Frontal ? RefineResult(refine_front2d(P, ro)) : refine_del2d(P, ro);
  out.stats = r.stats;
  if (!r.ok()) {
    out.error = r.error;
    return;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sub_keys;
  for (const Edge& e : subs) sub_keys.push_back(key(e.first, e.second));
  std::sort(sub_keys.begin(), sub_keys.end());
  for (std::uint32_t s = 0; s < P.corner.size(); ++s)
    if (!P.twin[s].valid() && P.alive(tri_of(Side{s})) &&
        std::binary_search(sub_keys.begin(), sub_keys.end(), key(P.org(Side{s}), P.dest(Side{s}))))
      P.side_flags[s] &= static_cast<std::uint8_t>(~kConstrained);
  P.compact();
  keep_for_merge(P);
}

}  // namespace

std::uint64_t saturated_count(double x) {
  // 2^64 as a double; llround is defined only below 2^63, so the top half goes by hand.
  constexpr double kTwo64 = 18446744073709551616.0;
  if (!(x < kTwo64)) return std::numeric_limits<std::uint64_t>::max();   // NaN, inf, huge
  if (!(x > 0)) return 0;
  return static_cast<std::uint64_t>(std::round(x));
}

std::uint64_t estimate_triangles(const TriangleStore& m, const PlaneSizeFn& size) {
  const std::vector<std::uint32_t> tris = live_triangles(m);
  std::vector<Vec2> c;
  std::vector<double> w;
  estimate_each(m, tris, size, c, w);
  return saturated_count(std::accumulate(w.begin(), w.end(), 0.0));
}

std::uint64_t estimate_triangles(const TriangleStore& m, const std::function<PlaneSizeFn()>& make_size, int threads) {
  const std::vector<std::uint32_t> tris = live_triangles(m);
  std::vector<Vec2> c;
  std::vector<double> w;
  estimate_each(m, tris, nullptr, c, w, make_size, threads);
  return saturated_count(std::accumulate(w.begin(), w.end(), 0.0));
}

std::uint32_t part_count(std::uint64_t estimate, const PartitionOptions& opt) {
  const double ratio = double(estimate) / double(std::max<std::uint64_t>(opt.part_triangles, 1));
  const int log2k = ratio > 1 ? static_cast<int>(std::lround(std::log2(ratio))) : 1;
  const std::uint32_t cap = std::max<std::uint32_t>(opt.max_parts, 2);
  if (log2k >= 31) return cap;
  return std::clamp<std::uint32_t>(1u << std::max(log2k, 1), 2, cap);
}

std::vector<std::uint32_t> bisect_parts(std::span<const Vec2> points, std::span<const double> weights,
                                        std::uint32_t parts) {
  std::vector<std::uint32_t> part(points.size(), 0), idx(points.size());
  std::iota(idx.begin(), idx.end(), 0u);
  auto split = [&](auto&& self, std::size_t begin, std::size_t end, std::uint32_t first, std::uint32_t count) -> void {
    if (count <= 1 || end - begin <= 1) {
      for (std::size_t i = begin; i < end; ++i) part[idx[i]] = first;
      return;
    }
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY, total = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const Vec2 p = points[idx[i]];
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      total += weights[idx[i]];
    }
    const bool along_x = x1 - x0 >= y1 - y0;
    const auto before = [&](std::uint32_t a, std::uint32_t b) {
      const double ca = along_x ? points[a].x : points[a].y, cb = along_x ? points[b].x : points[b].y;
      return ca != cb ? ca < cb : a < b;
    };
    // The left half takes items while its weight stays below half of the total; both
    // halves keep at least one item when there are two. With equal weights that count
    // does not depend on the order (the same sums), and only which items fall on each
    // side matters: a selection, not a sort (the blocked quality pass cuts millions).
    const double w0 = weights[idx[begin]];
    bool equal = true;
    for (std::size_t i = begin; i < end && equal; ++i) equal = weights[idx[i]] == w0;
    std::size_t mid = begin;
    double acc = 0;
    if (equal) {
      while (mid < end && acc + w0 <= 0.5 * total) acc += w0, ++mid;
      if (end - begin >= 2) mid = std::clamp(mid, begin + 1, end - 1);
      std::nth_element(idx.begin() + begin, idx.begin() + mid, idx.begin() + end, before);
    } else {
      std::sort(idx.begin() + begin, idx.begin() + end, before);
      while (mid < end && acc + weights[idx[mid]] <= 0.5 * total) acc += weights[idx[mid++]];
      if (end - begin >= 2) mid = std::clamp(mid, begin + 1, end - 1);
    }
    self(self, begin, mid, first, count / 2);
    self(self, mid, end, first + count / 2, count - count / 2);
  };
  split(split, 0, points.size(), 0, std::max<std::uint32_t>(parts, 1));
  return part;
}

std::vector<Vec2> subdivide_segment(Vec2 a, Vec2 b, const PlaneSizeFn& size) {
  std::vector<Vec2> out;
  const double len = norm(b - a);
  if (!(len > 0)) return out;
  const Vec2 probe[3] = {a, 0.5 * (a + b), b};
  double hp[3] = {0, 0, 0};
  size(probe, hp);
  const double hmin = std::min({hp[0], hp[1], hp[2]});
  if (!(hmin > 0) || !std::isfinite(hmin)) return out;
  const auto steps = static_cast<std::size_t>(std::clamp(std::ceil(4 * len / hmin), 2.0, 65536.0));
  std::vector<Vec2> s(steps + 1);
  std::vector<double> h(steps + 1), cum(steps + 1, 0.0);
  for (std::size_t i = 0; i <= steps; ++i) s[i] = a + (double(i) / double(steps)) * (b - a);
  s[steps] = b;
  for (std::size_t i = 0; i <= steps; i += kBatch) {
    const std::size_t n = std::min(kBatch, steps + 1 - i);
    size(std::span<const Vec2>(s.data() + i, n), std::span<double>(h.data() + i, n));
  }
  for (std::size_t i = 1; i <= steps; ++i) {
    if (!(h[i] > 0) || !std::isfinite(h[i])) return {};
    cum[i] = cum[i - 1] + 0.5 * (1 / h[i - 1] + 1 / h[i]) * (len / double(steps));
  }
  const double total = cum[steps];
  const auto n = static_cast<std::size_t>(std::max<std::uint64_t>(1, saturated_count(total)));
  std::size_t i = 1;
  for (std::size_t k = 1; k < n; ++k) {
    const double target = total * double(k) / double(n);
    while (i < steps && cum[i] < target) ++i;
    const double f = cum[i] > cum[i - 1] ? (target - cum[i - 1]) / (cum[i] - cum[i - 1]) : 0.5;
    out.push_back(a + ((double(i - 1) + f) / double(steps)) * (b - a));
  }
  return out;
}

namespace {

// The stages of refine_partitioned, in its order.

// Coarse pass: del2d at the scaled size (its vertices become vertices of the result).
// It starts from m itself, moved rather than copied: the result replaces m, and a copy
// held the face's boundary triangulation twice through the parts (at the full world's
// 3 km, some 300,000 boundary vertices). m is left empty on failure.
// With sizes by point and threads, its large batches (the first sizing of every
// triangle, 4096 at a time) are sized in chunks on the threads (sizes_in_chunks).
bool refine_coarse(Coarse& c, TriangleStore& m, const RefineOptions& base, const PlaneSizeFn& fine,
                   const std::function<PlaneSizeFn()>& make_size, int threads, const PartitionOptions& opt,
                   PartitionResult& res) {
  c.m = std::move(m);
  m = TriangleStore{};
  RefineOptions co = base;
  co.vertex_size_at = nullptr;
  const double f = opt.coarse_factor;
  const bool chunked = opt.sizes_by_point && threads > 1;
  co.size_at = [&fine, &make_size, f, chunked, threads](std::span<const Vec2> p, std::span<double> h) {
    if (chunked && p.size() >= 2 * kSizeChunk) sizes_in_chunks(p, h, make_size, threads);
    else fine(p, h);
    for (double& x : h) x *= f;
  };
  const RefineResult r = refine_del2d(c.m, co);
  add_stats(res.stats.refine, r.stats);
  if (!r.ok()) {
    res.error = "coarse refinement: " + r.error;
    return false;
  }
  return true;
}

// The cut: the final triangle count estimated from the coarse triangles, the part count
// from it, the coarse triangles bisected into that many parts of about equal weight.
// Returns the part count.
std::uint32_t cut_into_parts(Coarse& c, const std::vector<std::uint32_t>& tris, const PlaneSizeFn& fine,
                             const std::function<PlaneSizeFn()>& make_size, int threads, const PartitionOptions& opt,
                             PartitionResult& res) {
  std::vector<Vec2> centre;
  std::vector<double> weight;
  estimate_each(c.m, tris, fine, centre, weight, opt.sizes_by_point ? make_size : nullptr, threads);
  res.stats.coarse_triangles = tris.size();
  res.stats.estimate = saturated_count(std::accumulate(weight.begin(), weight.end(), 0.0));
  const std::uint32_t k = part_count(res.stats.estimate, opt);
  res.stats.parts = k;
  const std::vector<std::uint32_t> part = bisect_parts(centre, weight, k);
  c.part_of.assign(c.m.num_slots(), kNoIndex);
  c.part_tris.resize(k);
  for (std::size_t i = 0; i < tris.size(); ++i) {
    c.part_of[tris[i]] = part[i];
    c.part_tris[part[i]].push_back(tris[i]);
  }
  return k;
}

// Border edges: subdivided once, from the smaller vertex id. The borders are listed first;
// with sizes by point and threads, their points are then found in chunks of borders on the
// threads, each chunk with an evaluator of its own, and appended in border order.
void subdivide_borders(Coarse& c, const std::vector<std::uint32_t>& tris, const PlaneSizeFn& fine,
                       const std::function<PlaneSizeFn()>& make_size, int threads, const PartitionOptions& opt) {
  c.border_of_side.assign(c.m.corner.size(), kNoIndex);
  for (std::uint32_t t : tris)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s = side_of(TriId{t}, e);
      const Side o = c.m.twin[s.value];
      if (!o.valid() || c.part_of[tri_of(o).value] == c.part_of[t] || c.m.constrained(s)) continue;
      if (c.m.org(s).value > c.m.dest(s).value) continue;
      c.border_of_side[s.value] = c.border_of_side[o.value] = static_cast<std::uint32_t>(c.borders.size());
      c.borders.push_back(Border{c.m.org(s), c.m.dest(s), 0, 0});
    }
  std::vector<std::vector<Vec2>> pts(c.borders.size());
  const auto subdivide = [&c, &pts](std::size_t b, std::size_t e, const PlaneSizeFn& size) {
    for (std::size_t i = b; i < e; ++i)
      pts[i] = subdivide_segment(c.m.pos(c.borders[i].a), c.m.pos(c.borders[i].b), size);
  };
  constexpr std::size_t kBordersPerChunk = 64;
  if (opt.sizes_by_point && threads > 1 && c.borders.size() > kBordersPerChunk)
    parallel_for_chunks(threads, c.borders.size(), kBordersPerChunk,
                        [&](std::size_t b, std::size_t e) { subdivide(b, e, make_size()); });
  else
    subdivide(0, c.borders.size(), fine);
  for (std::size_t i = 0; i < c.borders.size(); ++i) {
    c.borders[i].first = static_cast<std::uint32_t>(c.border_xy.size());
    c.borders[i].count = static_cast<std::uint32_t>(pts[i].size());
    c.border_xy.insert(c.border_xy.end(), pts[i].begin(), pts[i].end());
  }
}

// The coarse vertices kept (Coarse::new_id): the input's n0 with their ids, then the
// coarse vertices on borders in coarse id order.
void number_kept_vertices(Coarse& c, std::uint32_t n0) {
  c.new_id.assign(c.m.num_vertices(), kNoIndex);
  for (std::uint32_t v = 0; v < n0; ++v) c.new_id[v] = v;
  for (const Border& br : c.borders)
    for (VertexId v : {br.a, br.b})
      if (v.value >= n0) c.new_id[v.value] = 0;   // kept; numbered below
  c.n_kept = n0;
  for (std::uint32_t v = n0; v < c.m.num_vertices(); ++v)
    if (c.new_id[v] != kNoIndex) c.new_id[v] = c.n_kept++;
}

// Each part meshed and refined on the threads, its size function its own (make_size's, or
// part_sizes's options); the first failing part's error, in part order, is the result's.
std::vector<PartOut> mesh_parts(const Coarse& c, std::uint32_t k, const RefineOptions& base, PartRefiner kind,
                                const std::function<PlaneSizeFn()>& make_size, int threads,
                                const std::function<void(std::uint32_t, std::uint32_t)>& on_parts,
                                const std::function<void(RefineOptions&)>& part_sizes, PartitionResult& res) {
  std::vector<PartOut> parts(k);
  std::function<void(std::size_t)> parts_done;
  if (on_parts) {
    on_parts(0, k);
    parts_done = [&](std::size_t done) { on_parts(static_cast<std::uint32_t>(done), k); };
  }
  parallel_for_chunks(
      threads, k, 1,
      [&](std::size_t b, std::size_t e) {
        for (std::size_t p = b; p < e; ++p) {
          if (part_sizes) {
            RefineOptions ro = base;
            part_sizes(ro);
            mesh_part(c, static_cast<std::uint32_t>(p), ro, kind, ro.size_at, parts[p]);
            continue;
          }
          const PlaneSizeFn size = make_size();
          mesh_part(c, static_cast<std::uint32_t>(p), base, kind, size, parts[p]);
        }
      },
      parts_done);
  for (std::uint32_t p = 0; p < k; ++p) {
    add_stats(res.stats.refine, parts[p].stats);
    if (!parts[p].error.empty() && res.error.empty()) res.error = fmt::format("part {}: {}", p, parts[p].error);
  }
  return parts;
}

// The parts copied into one store: vertices and triangles in part order, twins inside
// parts kept; vbase/tbase are each part's first vertex and triangle. Copied in waves of
// `threads` parts, each part on its own thread and freed once copied: the arrays are
// reserved up front and grown by one wave at a time, so the resident peak is about one
// mesh plus one wave of parts. The coarse mesh is freed first. Returns the sides on the
// parts' hulls (no twin yet), in part order.
std::vector<std::uint32_t> copy_parts(Coarse& c, std::vector<PartOut>& parts, const std::vector<std::uint64_t>& vbase,
                                      const std::vector<std::uint64_t>& tbase, int threads, TriangleStore& out) {
  const auto k = static_cast<std::uint32_t>(parts.size());
  out.xy.reserve(vbase[k]);
  for (std::uint32_t v = 0; v < c.m.num_vertices(); ++v)
    if (c.new_id[v] != kNoIndex) out.xy.push_back(c.m.xy[v]);
  out.xy.insert(out.xy.end(), c.border_xy.begin(), c.border_xy.end());
  out.corner.reserve(3 * tbase[k]);
  out.twin.reserve(3 * tbase[k]);
  out.side_flags.reserve(3 * tbase[k]);
  out.tri_flags.reserve(tbase[k]);
  c.m = TriangleStore{};
  std::vector<std::vector<std::uint32_t>> hull_of(k);
  const auto wave = static_cast<std::uint32_t>(std::max(threads, 1));
  for (std::uint32_t w0 = 0; w0 < k; w0 += wave) {
    const std::uint32_t w1 = std::min(k, w0 + wave);
    out.xy.resize(vbase[w1]);
    out.corner.resize(3 * tbase[w1]);
    out.twin.resize(3 * tbase[w1]);
    out.side_flags.resize(3 * tbase[w1]);
    out.tri_flags.resize(tbase[w1], 0);
    parallel_for_chunks(threads, w1 - w0, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t p = w0 + b; p < w0 + e; ++p) {
        PartOut& po = parts[p];
        const TriangleStore& P = po.st;
        for (std::uint32_t v = po.n_init; v < P.num_vertices(); ++v) out.xy[vbase[p] + v - po.n_init] = P.xy[v];
        const auto s0 = static_cast<std::uint32_t>(3 * tbase[p]);
        for (std::uint32_t x = 0; x < P.corner.size(); ++x) {
          const VertexId v = P.corner[x];
          out.corner[s0 + x] = VertexId{
              v.value < po.n_init ? po.global_of[v.value] : static_cast<std::uint32_t>(vbase[p] + v.value - po.n_init)};
          out.side_flags[s0 + x] = P.side_flags[x];
          if (P.twin[x].valid()) {
            out.twin[s0 + x] = Side{s0 + P.twin[x].value};
          } else {
            out.twin[s0 + x] = Side{};
            hull_of[p].push_back(s0 + x);
          }
        }
        po = PartOut{};
      }
    });
    // A part's arrays (about a megabyte each) come from the heap, not from their own
    // mappings: without this the parts freed here stay resident beside the merged arrays
    // (square, 10M triangles: 85 -> 63 bytes per triangle at the peak).
    release_free_memory();
  }
  std::vector<std::uint32_t> hull;
  for (const auto& h : hull_of) hull.insert(hull.end(), h.begin(), h.end());
  return hull;
}

// Twins across borders: the hull sides sorted by their vertex pair, each pair linked; a
// pair used twice in one direction, or by more than two sides, is the result's error.
void link_borders(TriangleStore& out, const std::vector<std::uint32_t>& hull, PartitionResult& res) {
  struct HullSide {
    std::uint32_t lo, hi, s;
  };
  std::vector<HullSide> hs;
  for (std::uint32_t s : hull) {
    const std::uint32_t a = out.corner[s].value, b = out.corner[next(Side{s}).value].value;
    hs.push_back({std::min(a, b), std::max(a, b), s});
  }
  std::sort(hs.begin(), hs.end(), [](const HullSide& x, const HullSide& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.s < y.s;
  });
  for (std::size_t i = 0; i < hs.size(); ++i) {
    std::size_t j = i;
    while (j + 1 < hs.size() && hs[j + 1].lo == hs[i].lo && hs[j + 1].hi == hs[i].hi) ++j;
    if (j == i + 1) {
      const Side a{hs[i].s}, b{hs[j].s};
      if (out.corner[a.value] == out.corner[next(b).value]) out.link(a, b);
      else res.error = "two parts use a border edge in the same direction";
    } else if (j > i + 1) {
      res.error = "a border edge is shared by more than two triangles";
    }
    i = j;
  }
}

// Merge: the parts into one store (copy_parts), twins across borders found by sorting the
// parts' hull sides by their vertex pair (link_borders); m replaced on success.
void merge_parts(Coarse& c, std::vector<PartOut>& parts, const RefineOptions& base, int threads, TriangleStore& m,
                 PartitionResult& res) {
  const auto k = static_cast<std::uint32_t>(parts.size());
  const std::uint32_t n_shared = c.n_kept + static_cast<std::uint32_t>(c.border_xy.size());
  std::vector<std::uint64_t> vbase(k + 1, n_shared), tbase(k + 1, 0);
  for (std::uint32_t p = 0; p < k; ++p) {
    vbase[p + 1] = vbase[p] + (parts[p].st.num_vertices() - parts[p].n_init);
    tbase[p + 1] = tbase[p] + parts[p].st.num_slots();
  }
  if (vbase[k] > base.max_vertices || 3 * tbase[k] >= kNoIndex) {
    res.error = "refinement stopped at the vertex limit";
    return;
  }
  TriangleStore out;
  const std::vector<std::uint32_t> hull = copy_parts(c, parts, vbase, tbase, threads, out);
  link_borders(out, hull, res);
  if (!res.ok()) return;
  out.rebuild_out_side();
  m = std::move(out);
}

}  // namespace

PartitionResult refine_partitioned(TriangleStore& m, const RefineOptions& base, PartRefiner kind,
                                   const std::function<PlaneSizeFn()>& make_size, const PartitionOptions& opt,
                                   int threads,
                                   const std::function<void(std::uint32_t, std::uint32_t)>& on_parts,
                                   const std::function<void(RefineOptions&)>& part_sizes) {
  PartitionResult res;
  auto t0 = std::chrono::steady_clock::now();
  const PlaneSizeFn fine = make_size();
  Coarse c;
  const std::uint32_t n0 = m.num_vertices();
  if (!refine_coarse(c, m, base, fine, make_size, threads, opt, res)) return res;
  const std::vector<std::uint32_t> tris = live_triangles(c.m);
  const std::uint32_t k = cut_into_parts(c, tris, fine, make_size, threads, opt, res);
  subdivide_borders(c, tris, fine, make_size, threads, opt);
  number_kept_vertices(c, n0);
  res.stats.border_edges = c.borders.size();
  res.stats.border_points = c.border_xy.size();
  res.stats.seconds_coarse = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  std::vector<PartOut> parts = mesh_parts(c, k, base, kind, make_size, threads, on_parts, part_sizes, res);
  res.stats.seconds_parts = seconds_since(t0);
  if (!res.ok()) return res;

  t0 = std::chrono::steady_clock::now();
  merge_parts(c, parts, base, threads, m, res);
  if (!res.ok()) return res;
  res.stats.seconds_merge = seconds_since(t0);
  return res;
}

}  // namespace sm
