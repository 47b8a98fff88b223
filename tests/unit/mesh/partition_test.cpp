// mesh/partition: bisection balance, part count, border subdivision at a graded size, and
// refine_partitioned on planar domains: valid conforming topology, quality close to the
// unpartitioned refinement, the same bytes for 1, 2 and 4 threads.
#include "mesh/partition.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <thread>
#include <vector>

#include "mesh/check.h"
#include "mesh/frontal.h"
#include "mesh/geometry.h"
#include "mesh/modify/smooth.h"
#include "exact/predicates.h"
#include "mesh/quality.h"
#include "testing_domains.h"

using namespace sm;

namespace {

PlaneSizeFn uniform(double h) {
  return [h](std::span<const Vec2>, std::span<double> out) { std::fill(out.begin(), out.end(), h); };
}

// Size growing linearly with x: h = h0 (1 + 4 x) on the unit square.
PlaneSizeFn graded(double h0) {
  return [h0](std::span<const Vec2> p, std::span<double> out) {
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = h0 * (1 + 4 * p[i].x);
  };
}

// The unit square with two circular holes, boundary at size h, as a CDT of the domain.
TriangleStore square_with_holes(double h, std::vector<Edge>* edges) {
  TriangleStore m;
  const Loop outer = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  const Loop a = testing::circle_loop(m, {0.3, 0.35}, 0.12, h, true);
  const Loop b = testing::circle_loop(m, {0.7, 0.65}, 0.1, h, true);
  REQUIRE(testing::boundary_mesh(m, {outer, a, b}, edges));
  return m;
}

bool same(const TriangleStore& a, const TriangleStore& b) {
  return a.xy == b.xy && a.corner == b.corner && a.twin == b.twin && a.side_flags == b.side_flags &&
         a.tri_flags == b.tri_flags;
}

// Every triangle strictly counter-clockwise (exact).
std::size_t inverted(const TriangleStore& m) {
  std::size_t bad = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t}) &&
        orient2d(m.pos(m.vertex(TriId{t}, 0)), m.pos(m.vertex(TriId{t}, 1)), m.pos(m.vertex(TriId{t}, 2))) !=
            Sign::Positive)
      ++bad;
  return bad;
}

double total_area(const TriangleStore& m) {
  double s = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    const Vec2 a = m.pos(m.vertex(TriId{t}, 0)), b = m.pos(m.vertex(TriId{t}, 1)), c = m.pos(m.vertex(TriId{t}, 2));
    s += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return s;
}

// Hull edges (twin kNone) of m as sorted undirected pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t>> hull_edges(const TriangleStore& m) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (m.alive(tri_of(Side{s})) && !m.twin[s].valid())
      out.push_back(std::minmax(m.org(Side{s}).value, m.dest(Side{s}).value));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("partition: part_count is a power of two from the estimate only") {
  PartitionOptions o;
  o.part_triangles = 100000;
  CHECK(part_count(0, o) == 2);
  CHECK(part_count(150000, o) == 2);
  CHECK(part_count(400000, o) == 4);
  CHECK(part_count(1000000, o) == 8);     // 10 -> 2^3
  CHECK(part_count(1500000, o) == 16);    // 15 -> 2^4 (log2 15 = 3.9)
  CHECK(part_count(10000000, o) == 128);  // 100 -> 2^7 (log2 100 = 6.6)
  o.max_parts = 64;
  CHECK(part_count(10000000, o) == 64);
}

TEST_CASE("partition: bisect_parts balances the weights and cuts along the longer side") {
  // 64 x 16 grid, weight growing with x: 4 parts, each about a quarter of the weight.
  std::vector<Vec2> p;
  std::vector<double> w;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 64; ++i) p.push_back({i + 0.5, j + 0.5}), w.push_back(1 + i);
  const std::vector<std::uint32_t> part = bisect_parts(p, w, 4);
  std::vector<double> sum(4, 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    REQUIRE(part[i] < 4);
    sum[part[i]] += w[i];
  }
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  for (double s : sum) CHECK(s == doctest::Approx(total / 4).epsilon(0.03));
  // The first cut is vertical (the box is 4 times wider): parts 0, 1 left of parts 2, 3,
  // and the heavy right half is narrower than the left one.
  double max_left = 0, min_right = 1e9;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (part[i] < 2) max_left = std::max(max_left, p[i].x);
    else min_right = std::min(min_right, p[i].x);
  CHECK(max_left <= min_right);
  CHECK(min_right > 32);
  // Deterministic, and one part for one point.
  CHECK(bisect_parts(p, w, 4) == part);
  CHECK(bisect_parts(std::vector<Vec2>{{0, 0}}, std::vector<double>{1}, 8) == std::vector<std::uint32_t>{0});
}

TEST_CASE("partition: subdivide_segment follows the integral of 1/h") {
  // Uniform: a length-1 segment at h = 0.1 gets 9 inner points 0.1 apart.
  const std::vector<Vec2> u = subdivide_segment({0, 0}, {1, 0}, uniform(0.1));
  REQUIRE(u.size() == 9);
  for (std::size_t k = 0; k < u.size(); ++k) CHECK(u[k].x == doctest::Approx(0.1 * (k + 1)).epsilon(1e-9));
  // h = 0.01 (1 + 4 x): integral of 1/h over [0, 1] is ln(5) / 0.04 = 40.2 -> 40 pieces; the
  // point k sits where ln(1 + 4x) / 0.04 = k * 40.24 / 40.
  const std::vector<Vec2> g = subdivide_segment({0, 0}, {1, 0}, graded(0.01));
  REQUIRE(g.size() == 39);
  const double total = std::log(5.0) / 0.04;
  for (std::size_t k = 0; k < g.size(); ++k) {
    const double x = (std::exp(0.04 * total * double(k + 1) / 40) - 1) / 4;
    CHECK(g[k].x == doctest::Approx(x).epsilon(1e-3));
    CHECK(g[k].y == 0);
  }
  // Shorter than the size: no inner point; reversed: the same points in reverse order.
  CHECK(subdivide_segment({0, 0}, {0.05, 0}, uniform(0.1)).empty());
  const std::vector<Vec2> r = subdivide_segment({1, 0}, {0, 0}, uniform(0.1));
  REQUIRE(r.size() == 9);
  CHECK(r[0].x == doctest::Approx(0.9));
}

TEST_CASE(
    "partition: refine_partitioned on a square with holes is conforming, graded, and the same for 1, 2, 4 threads") {
  for (PartRefiner kind : {PartRefiner::Del2d, PartRefiner::Frontal}) {
    CAPTURE(kind == PartRefiner::Frontal);
    std::vector<Edge> edges;
    const double h0 = 0.004;
    const TriangleStore cdt = square_with_holes(h0, &edges);
    const std::uint32_t n0 = cdt.num_vertices();
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary = hull_edges(cdt);
    RefineOptions ro;
    ro.radius_limit = kind == PartRefiner::Del2d ? 0.73 : ro.radius_limit;
    PartitionOptions po;
    po.part_triangles = 4000;
    const auto make = [h0] { return graded(h0); };
    const std::uint64_t est = estimate_triangles(cdt, graded(h0));
    CHECK(est > 15000);
    CHECK(est < 30000);
    TriangleStore m1 = cdt;
    const PartitionResult r1 = refine_partitioned(m1, ro, kind, make, po, 1);
    INFO(r1.error);
    REQUIRE(r1.ok());
    MESSAGE("estimate " << r1.stats.estimate << ", " << r1.stats.parts << " parts, " << r1.stats.coarse_triangles
                        << " coarse triangles, " << r1.stats.border_points << " border points, "
                        << m1.num_triangles() << " triangles");
    CHECK(r1.stats.parts == part_count(r1.stats.estimate, po));
    CHECK(r1.stats.parts >= 4);
    CHECK(r1.stats.border_points > 100);
    // The input vertices keep their ids and places.
    REQUIRE(m1.num_vertices() > n0);
    for (std::uint32_t v = 0; v < n0; ++v) REQUIRE(m1.xy[v] == cdt.xy[v]);
    CHECK(check_topology(m1).error == "");
    CHECK(check_constraints(m1, edges).ok());
    CHECK(inverted(m1) == 0);
    CHECK(hull_edges(m1) == boundary);
    CHECK(total_area(m1) == doctest::Approx(total_area(cdt)).epsilon(1e-12));
    // Only the domain's edges are constrained: borders are ordinary edges.
    std::size_t constrained = 0;
    for (std::uint32_t s = 0; s < m1.corner.size(); ++s)
      if (m1.alive(tri_of(Side{s})) && m1.constrained(Side{s})) ++constrained;
    CHECK(constrained == boundary.size());
    // Estimated within 15% of the final count.
    CHECK(double(m1.num_triangles()) == doctest::Approx(double(r1.stats.estimate)).epsilon(0.15));
    for (int threads : {2, 4}) {
      TriangleStore mt = cdt;
      // Progress: (0, K) first, then parts done up to (K, K), all on this thread.
      std::vector<std::pair<std::uint32_t, std::uint32_t>> calls;
      bool other_thread = false;
      const std::thread::id caller = std::this_thread::get_id();
      const auto on_parts = [&](std::uint32_t done, std::uint32_t parts) {
        other_thread = other_thread || std::this_thread::get_id() != caller;
        calls.emplace_back(done, parts);
      };
      REQUIRE(refine_partitioned(mt, ro, kind, make, po, threads, on_parts).ok());
      CHECK(same(m1, mt));
      CHECK_FALSE(other_thread);
      REQUIRE(calls.size() >= 2);
      CHECK(calls.front() == std::pair<std::uint32_t, std::uint32_t>{0, r1.stats.parts});
      CHECK(calls.back() == std::pair<std::uint32_t, std::uint32_t>{r1.stats.parts, r1.stats.parts});
      CHECK(std::is_sorted(calls.begin(), calls.end()));
    }
    // Quality after one smoothing pass, against the unpartitioned refinement.
    TriangleStore whole = cdt;
    RefineOptions wo = ro;
    wo.size_at = graded(h0);
    REQUIRE((kind == PartRefiner::Frontal ? RefineResult(refine_front2d(whole, wo)) : refine_del2d(whole, wo)).ok());
    smooth_laplacian(whole, 1);
    smooth_laplacian(m1, 1);
    CHECK(check_topology(m1).ok());
    CHECK(check_delaunay(m1, PlanarGeometry{&m1.xy}).ok());
    const auto size = [h0](Vec2 p) { return h0 * (1 + 4 * p.x); };
    const QualityStats qp = mesh_quality(m1, size), qw = mesh_quality(whole, size);
    MESSAGE("parts: rho>0.9 " << qp.share_rho_09 << " min " << qp.min_rho << " in [0.7,1.4] " << qp.share_len_07_14
                              << "; whole: " << qw.share_rho_09 << " min " << qw.min_rho << " "
                              << qw.share_len_07_14);
    // The holes' boundaries are at h0 where the size is larger: their triangles set min rho
    // (0.11-0.23 with or without parts).
    CHECK(qp.share_len_07_14 >= qw.share_len_07_14 - 0.01);
    CHECK(qp.min_rho > 0.1);
    CHECK(qp.share_rho_09 > qw.share_rho_09 - 0.02);
    CHECK(double(qp.triangles) == doctest::Approx(double(qw.triangles)).epsilon(0.03));
  }
}

TEST_CASE("partition: sizes by point sized in chunks on the threads give the same stores and estimate") {
  // A fine boundary (about 5,400 vertices) under a coarser graded size: the coarse pass's
  // first batches (4096 triangles), the cut's estimate (over 4096 coarse triangles) and the
  // borders (over 64) are all large enough to be cut into chunks.
  std::vector<Edge> edges;
  const TriangleStore cdt = square_with_holes(0.001, &edges);
  REQUIRE(cdt.num_triangles() > 4096);
  const double h0 = 0.003;
  std::atomic<int> made{0};
  const auto make = [h0, &made] {
    ++made;
    return graded(h0);
  };
  const std::uint64_t est = estimate_triangles(cdt, graded(h0));
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    made = 0;
    CHECK(estimate_triangles(cdt, make, threads) == est);
    CHECK(made == (threads > 1 ? int((cdt.num_triangles() + 4095) / 4096) : 1));
  }
  RefineOptions ro;
  ro.radius_limit = 0.73;
  PartitionOptions po;
  po.part_triangles = 2000;
  TriangleStore m1 = cdt;
  const PartitionResult r1 = refine_partitioned(m1, ro, PartRefiner::Frontal, make, po, 1);
  REQUIRE(r1.ok());
  CHECK(r1.stats.coarse_triangles > 4096);
  CHECK(r1.stats.border_edges > 64);
  po.sizes_by_point = true;
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    made = 0;
    TriangleStore mt = cdt;
    const PartitionResult rt = refine_partitioned(mt, ro, PartRefiner::Frontal, make, po, threads);
    REQUIRE(rt.ok());
    CHECK(same(m1, mt));
    CHECK(rt.stats.estimate == r1.stats.estimate);
    CHECK(rt.stats.border_points == r1.stats.border_points);
    // One evaluator for the serial steps and one a part, and with threads one a chunk more.
    if (threads == 1) CHECK(made == int(1 + r1.stats.parts));
    else CHECK(made > int(1 + r1.stats.parts + r1.stats.coarse_triangles / 4096));
  }
}

TEST_CASE("partition: a non-positive size is an error, not a crash") {
  std::vector<Edge> edges;
  const TriangleStore cdt = square_with_holes(0.01, &edges);
  for (double bad : {0.0, -1.0, std::nan("")}) {
    CAPTURE(bad);
    TriangleStore m = cdt;
    const auto make = [bad]() -> PlaneSizeFn {
      return [bad](std::span<const Vec2> p, std::span<double> h) {
        for (std::size_t i = 0; i < p.size(); ++i) h[i] = p[i].x > 0.5 ? bad : 0.01;
      };
    };
    const PartitionResult r = refine_partitioned(m, RefineOptions{}, PartRefiner::Del2d, make, PartitionOptions{}, 2);
    CHECK_FALSE(r.ok());
    CHECK(r.error.find("positive") != std::string::npos);
    // The coarse pass took m's arrays (moved, not copied: partition.h).
    CHECK(m.num_vertices() == 0);
    CHECK(m.num_slots() == 0);
  }
}

TEST_CASE("partition: saturated_count never converts out of range") {
  CHECK(saturated_count(0) == 0);
  CHECK(saturated_count(-5) == 0);
  CHECK(saturated_count(2.5) == 3);
  CHECK(saturated_count(1e12) == 1000000000000ull);
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  CHECK(saturated_count(1e30) == kMax);
  CHECK(saturated_count(std::numeric_limits<double>::infinity()) == kMax);
  CHECK(saturated_count(std::numeric_limits<double>::quiet_NaN()) == kMax);
  CHECK(saturated_count(1.5e19) == 15000000000000000000ull);   // above 2^63, below 2^64
}

TEST_CASE("partition: estimate_triangles of a vanishing size is the largest count, not a wrapped one") {
  TriangleStore m;
  const Loop l = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25, false);
  REQUIRE(testing::boundary_mesh(m, {l}));
  // 1/h^2 overflows to inf (a size of zero is skipped: the refiners refuse it by name).
  const PlaneSizeFn vanishing = [](std::span<const Vec2>, std::span<double> h) {
    for (double& x : h) x = 1e-200;
  };
  CHECK(estimate_triangles(m, vanishing) == std::numeric_limits<std::uint64_t>::max());
  const PlaneSizeFn tiny = [](std::span<const Vec2>, std::span<double> h) {
    for (double& x : h) x = 1e-6;
  };
  CHECK(static_cast<double>(estimate_triangles(m, tiny)) ==
        doctest::Approx(1 / (1e-12 * std::sqrt(3) / 4)).epsilon(0.01));
}
