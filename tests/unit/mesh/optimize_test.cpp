// optimize_quality after del2d and front2d on a square, on a stereographic cap measured on
// the sphere, on real GSHHG coastlines and on a bare CDT: the worst rho rises, the share
// above 0.9 does not fall, the boundary and its edges stay, nothing inverts, same bytes twice.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <span>
#include <string>

#include "mesh/check.h"
#include "mesh/frontal.h"
#include "mesh/modify/optimize.h"
#include "mesh/modify/smooth.h"
#include "mesh/quality.h"
#include "mesh/refine.h"
#include "testing_coast.h"
#include "testing_domains.h"
#include "testing_sphere.h"

using namespace sm;

namespace {

bool same_points_corners_twins(const TriangleStore& a, const TriangleStore& b) {
  return a.xy.size() == b.xy.size() && std::memcmp(a.xy.data(), b.xy.data(), a.xy.size() * sizeof(Vec2)) == 0 &&
         a.corner == b.corner;
}

// The invariants every test ends with: valid, ccw (exact), constraints present and
// flagged, vertices [0, fixed) where they were.
void check_invariants(const TriangleStore& m, const std::vector<Edge>& edges, const std::vector<Vec2>& fixed_xy) {
  const CheckResult topo = check_topology(m);
  INFO(topo.error);
  REQUIRE(topo.ok());
  const CheckResult cons = check_constraints(m, edges);
  INFO(cons.error);
  REQUIRE(cons.ok());
  for (std::size_t v = 0; v < fixed_xy.size(); ++v) REQUIRE(m.xy[v] == fixed_xy[v]);
}

struct Square {
  TriangleStore m;
  std::vector<Edge> edges;
  std::uint32_t fixed = 0;
};

// The unit square at size h, refined by del2d or front2d, with one Laplacian pass (the
// face driver's Mesh.Smoothing = 1) and a circular hole.
Square square(double h, bool frontal) {
  Square s;
  const Loop sq = testing::polygon_loop(s.m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  const Loop hole = testing::circle_loop(s.m, {0.4, 0.6}, 0.15, h, true);
  REQUIRE(testing::boundary_mesh(s.m, {sq, hole}, &s.edges));
  s.fixed = s.m.num_vertices();
  RefineOptions opt;
  opt.size = h;
  REQUIRE((frontal ? refine_front2d(s.m, opt) : refine_del2d(s.m, opt)).ok());
  smooth_laplacian(s.m, 1);
  return s;
}

// rho of the chord triangles on the unit sphere: min and share above 0.9.
std::pair<double, double> sphere_rho(const TriangleStore& m) {
  double mn = 1;
  std::size_t good = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
    if (!m.alive(TriId{t})) continue;
    const Vec3 a = testing::unit_on_sphere(m.pos(m.vertex(TriId{t}, 0))),
               b = testing::unit_on_sphere(m.pos(m.vertex(TriId{t}, 1))),
               c = testing::unit_on_sphere(m.pos(m.vertex(TriId{t}, 2)));
    const double la = norm(b - c), lb = norm(c - a), lc = norm(a - b), ar2 = norm(cross(b - a, c - a));
    const double q = 4 * ar2 * ar2 / ((la + lb + lc) * la * lb * lc);
    mn = std::min(mn, q);
    good += q > 0.9;
  }
  return {mn, double(good) / m.num_triangles()};
}

}  // namespace

TEST_CASE("optimize_quality: front2d square with a hole, the worst rho rises above 0.8") {
  Square s = square(0.01, true);
  const std::vector<Vec2> fixed_xy(s.m.xy.begin(), s.m.xy.begin() + s.fixed);
  const QualityStats before = mesh_quality(s.m);
  TriangleStore copy = s.m;
  const OptimizeStats st = optimize_quality(s.m, s.fixed);
  check_invariants(s.m, s.edges, fixed_xy);
  const QualityStats after = mesh_quality(s.m);
  MESSAGE("front2d h 0.01: rho min " << before.min_rho << " -> " << after.min_rho << ", > 0.9 " << before.share_rho_09
                                     << " -> " << after.share_rho_09 << "; " << st.moves << " moves, " << st.swaps
                                     << " swaps");
  CHECK(before.min_rho < 0.8);
  CHECK(after.min_rho >= 0.8);
  CHECK(st.min_before == doctest::Approx(before.min_rho));
  CHECK(st.min_after == doctest::Approx(after.min_rho));
  CHECK(after.share_rho_09 >= before.share_rho_09);
  CHECK(after.triangles == before.triangles);
  CHECK(after.share_len_07_14 >= before.share_len_07_14 - 1e-3);
  optimize_quality(copy, s.fixed);
  CHECK(same_points_corners_twins(copy, s.m));
}

TEST_CASE("optimize_quality: del2d square with a hole, the worst rho rises from 0.50 to above 0.65") {
  Square s = square(0.01, false);
  const std::vector<Vec2> fixed_xy(s.m.xy.begin(), s.m.xy.begin() + s.fixed);
  const QualityStats before = mesh_quality(s.m);
  SUBCASE("defaults (threshold 0.9): the share above 0.9 rises from 86% to above 98% too") {
    const OptimizeStats st = optimize_quality(s.m, s.fixed);
    check_invariants(s.m, s.edges, fixed_xy);
    const QualityStats after = mesh_quality(s.m);
    MESSAGE("del2d h 0.01: rho min " << before.min_rho << " -> " << after.min_rho << ", > 0.9 "
                                     << before.share_rho_09 << " -> " << after.share_rho_09 << "; " << st.moves
                                     << " moves, " << st.swaps << " swaps");
    CHECK(before.min_rho < 0.6);
    CHECK(after.min_rho > 0.65);
    CHECK(after.share_rho_09 > 0.98);
    CHECK(after.share_len_07_14 >= before.share_len_07_14 - 1e-3);
  }
  SUBCASE("cheap: threshold 0.75, sacrifices only below 0.7") {
    OptimizeOptions opt;
    opt.threshold = 0.75;
    opt.sacrifice_below = 0.7;
    const OptimizeStats st = optimize_quality(s.m, s.fixed, opt);
    check_invariants(s.m, s.edges, fixed_xy);
    const QualityStats after = mesh_quality(s.m);
    MESSAGE("del2d h 0.01 cheap: rho min " << before.min_rho << " -> " << after.min_rho << ", > 0.9 "
                                           << before.share_rho_09 << " -> " << after.share_rho_09 << "; "
                                           << st.moves << " moves");
    CHECK(after.min_rho > 0.7);
    CHECK(after.share_rho_09 >= before.share_rho_09);
    CHECK(st.bad_after < st.bad_before / 4);
  }
  SUBCASE("cheap with a slack of 0.1% of the triangles for the share above 0.9") {
    OptimizeOptions opt;
    opt.threshold = 0.75;
    opt.sacrifice_below = 0.7;
    opt.max_share_loss = 1e-3;
    optimize_quality(s.m, s.fixed, opt);
    check_invariants(s.m, s.edges, fixed_xy);
    const QualityStats after = mesh_quality(s.m);
    MESSAGE("del2d h 0.01 cheap with slack: rho min " << before.min_rho << " -> " << after.min_rho << ", > 0.9 "
                                                      << before.share_rho_09 << " -> " << after.share_rho_09);
    CHECK(after.min_rho > 0.7);
    CHECK(after.share_rho_09 >= before.share_rho_09 - 1e-3);
  }
}

TEST_CASE("optimize_quality: PolarSphere cap measured on the sphere (to_space)") {
  const double delta = 0.03;
  for (bool frontal : {false, true}) {
    CAPTURE(frontal);
    TriangleStore m;
    const Loop cap = testing::cap_loop(m, delta);
    std::vector<Edge> edges;
    REQUIRE(testing::boundary_mesh(m, {cap}, &edges));
    const std::uint32_t fixed = m.num_vertices();
    const std::vector<Vec2> fixed_xy = m.xy;
    RefineOptions ro;
    ro.size_at = testing::stereo_size(delta);
    REQUIRE((frontal ? refine_front2d(m, ro) : refine_del2d(m, ro)).ok());
    smooth_laplacian(m, 1);
    const auto [min0, share0] = sphere_rho(m);
    OptimizeOptions opt;
    opt.to_space = testing::unit_on_sphere;
    TriangleStore copy = m;
    const OptimizeStats st = optimize_quality(m, fixed, opt);
    optimize_quality(copy, fixed, opt);
    CHECK(same_points_corners_twins(copy, m));
    check_invariants(m, edges, fixed_xy);
    const auto [min1, share1] = sphere_rho(m);
    MESSAGE(std::string(frontal ? "front2d" : "del2d")
            << " cap: sphere rho min " << min0 << " -> " << min1 << ", > 0.9 " << share0 << " -> " << share1 << "; "
            << st.moves << " moves");
    CHECK(st.min_before == doctest::Approx(min0));
    CHECK(st.min_after == doctest::Approx(min1));
    CHECK(min1 > min0 + 0.1);
    CHECK(min1 > (frontal ? 0.85 : 0.78));
    CHECK(share1 > (frontal ? 0.999 : 0.98));
    const testing::SphereStats ss = testing::sphere_stats(m, delta);
    CHECK(ss.in_07_14 > 0.95);
  }
}

TEST_CASE("optimize_quality: GSHHG crude world coastlines, raw vertices (close boundary points)") {
  // The ocean of world_c.txt in the stereographic plane with every raw coast vertex as a
  // boundary node, refined by front2d at 150 km: triangles of three coast nodes stay
  // (forced by the 1D mesh), the others must be lifted.
  const auto rings = testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(rings.size() > 100);
  std::vector<testing::RingCurve> curves;
  for (const auto& r : rings) curves.emplace_back(r);
  BoundaryProblem p = testing::coast_problem(curves, 0);
  const BoundaryResult r = recover_boundary(p, [&](std::uint32_t c, double t) { return curves[c].at(t); });
  REQUIRE(r.ok());
  const std::vector<Loop> loops = testing::ocean_loops(p, rings);
  TriangleStore m = r.mesh;
  REQUIRE(remove_outside(m, PlanarGeometry{&m.xy}, loops).ok());
  const std::uint32_t fixed = m.num_vertices();
  const std::vector<Vec2> fixed_xy = m.xy;
  RefineOptions ro;
  ro.size_at = testing::stereo_size(150.0 / 6371.0);
  REQUIRE(refine_front2d(m, ro).ok());
  smooth_laplacian(m, 1);
  // Worst rho of the triangles whose three vertices may move (a triangle with two coast
  // nodes closer than the local size, on one edge or on two nearly touching islands, is
  // a needle whatever the pass does), and the number of triangles below 0.5.
  const auto measure = [&](const TriangleStore& x) {
    double free_min = 1;
    std::size_t below = 0;
    for (std::uint32_t t = 0; t < x.num_slots(); ++t) {
      if (!x.alive(TriId{t})) continue;
      const VertexId a = x.vertex(TriId{t}, 0), b = x.vertex(TriId{t}, 1), c = x.vertex(TriId{t}, 2);
      const double q = rho(x.pos(a), x.pos(b), x.pos(c));
      below += q < 0.5;
      if (a.value >= fixed && b.value >= fixed && c.value >= fixed) free_min = std::min(free_min, q);
    }
    return std::pair{free_min, below};
  };
  const auto [free0, below0] = measure(m);
  const QualityStats q0 = mesh_quality(m);
  TriangleStore copy = m;
  const OptimizeStats st = optimize_quality(m, fixed);
  check_invariants(m, r.edges, fixed_xy);
  const auto [free1, below1] = measure(m);
  const QualityStats q1 = mesh_quality(m);
  MESSAGE("world_c: " << q1.triangles << " triangles; rho min " << q0.min_rho << " -> " << q1.min_rho
                      << ", of free vertices " << free0 << " -> " << free1 << ", below 0.5 " << below0 << " -> "
                      << below1 << ", > 0.9 " << q0.share_rho_09 << " -> " << q1.share_rho_09 << "; " << st.moves
                      << " moves, " << st.swaps << " swaps");
  CHECK(q1.min_rho >= q0.min_rho);
  CHECK(free1 > free0 + 0.1);
  CHECK(free1 > 0.15);
  CHECK(below1 < below0);
  CHECK(q1.share_rho_09 >= q0.share_rho_09);
  optimize_quality(copy, fixed);
  CHECK(same_points_corners_twins(copy, m));
}

TEST_CASE("optimize_quality: a bare CDT of a many-sided polygon, where only swaps can act") {
  TriangleStore m;
  const Loop l = testing::circle_loop(m, {0, 0}, 1, 0.25, false);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {l}, &edges));
  const std::uint32_t n = m.num_vertices();
  const std::vector<Vec2> fixed_xy = m.xy;
  const QualityStats before = mesh_quality(m);
  const OptimizeStats st = optimize_quality(m, 0);  // hull vertices are fixed anyway
  check_invariants(m, edges, fixed_xy);
  CHECK(m.num_vertices() == n);
  CHECK(st.moves == 0);
  CHECK(st.swaps > 0);
  const QualityStats after = mesh_quality(m);
  // The ears (three consecutive polygon vertices) cannot change, so the worst stays; the
  // swaps only ever raise the worse triangle of a pair.
  CHECK(after.min_rho == doctest::Approx(before.min_rho));
  CHECK(after.share_rho_09 >= before.share_rho_09);
}

TEST_CASE("optimize_quality: compound changes round short boundary edges (dams) decided before their moves") {
  // A square at size 0.1 with a channel 0.12 wide (its triangles span it, every corner on
  // the boundary), edges of 0.01 to 0.02 between edges of 0.1 on the channel and the
  // square's top (the dams across narrow passages of a coast): many compound changes
  // there make a new triangle of fixed corners below the worst rho round the quad, and
  // fail whatever the moves would do.
  TriangleStore m;
  const Loop l = testing::polygon_loop(m,
                                       {{0, 0}, {1, 0}, {1, 0.45}, {2, 0.45}, {2, 0.57}, {1.51, 0.57}, {1.5, 0.57},
                                        {1.215, 0.57}, {1.2, 0.57}, {1, 0.57}, {1, 1}, {0.21, 1}, {0.2, 1}, {0, 1}},
                                       0.1, false);
  std::vector<Edge> edges;
  REQUIRE(testing::boundary_mesh(m, {l}, &edges));
  const std::uint32_t fixed = m.num_vertices();
  RefineOptions ro;
  ro.size = 0.1;
  REQUIRE(refine_del2d(m, ro).ok());
  smooth_laplacian(m, 1);
  const std::vector<Vec2> fixed_xy(m.xy.begin(), m.xy.begin() + fixed);
  const QualityStats before = mesh_quality(m);
  TriangleStore copy = m;
  const OptimizeStats st = optimize_quality(m, fixed);
  check_invariants(m, edges, fixed_xy);
  const QualityStats after = mesh_quality(m);
  MESSAGE("dams: rho min " << before.min_rho << " -> " << after.min_rho << "; compound changes " << st.compound_tried
                           << ", decided before their moves " << st.compound_pinned << ", failed before "
                           << st.compound_repeated);
  CHECK(st.compound_pinned > 0);
  CHECK(st.compound_repeated > 0);
  CHECK(st.compound_pinned + st.compound_repeated < st.compound_tried);
  CHECK(after.min_rho >= before.min_rho);
  CHECK(after.share_rho_09 >= before.share_rho_09);
  optimize_quality(copy, fixed);
  CHECK(same_points_corners_twins(copy, m));
}

TEST_CASE("optimize_quality: the same bytes and stats on 1, 2 and 3 threads (the scans in chunks)") {
  // Over 16384 triangle slots: the first and last scans run in several chunks.
  const Square base = square(0.008, false);
  REQUIRE(base.m.num_slots() > 2 * 16384);   // three chunks at least
  std::vector<TriangleStore> out;
  std::vector<OptimizeStats> stats;
  for (int threads : {1, 2, 3}) {
    Square s = base;
    OptimizeOptions oo;
    oo.threshold = 0.75, oo.sacrifice_below = 0.7, oo.max_share_loss = 1e-4;   // the face driver's del2d settings
    oo.threads = threads;
    stats.push_back(optimize_quality(s.m, s.fixed, oo));
    std::vector<Vec2> fixed_xy(base.m.xy.begin(), base.m.xy.begin() + base.fixed);
    check_invariants(s.m, s.edges, fixed_xy);
    out.push_back(std::move(s.m));
  }
  for (std::size_t i = 1; i < out.size(); ++i) {
    CHECK(same_points_corners_twins(out[0], out[i]));
    CHECK(stats[i].bad_before == stats[0].bad_before);
    CHECK(stats[i].bad_after == stats[0].bad_after);
    CHECK(stats[i].min_before == stats[0].min_before);
    CHECK(stats[i].min_after == stats[0].min_after);
    CHECK(stats[i].swaps == stats[0].swaps);
    CHECK(stats[i].moves == stats[0].moves);
  }
  CHECK(stats[0].min_after > stats[0].min_before);
}

TEST_CASE("optimize_quality: candidates on the current position are not measured again, the same bytes") {
  // The line searches skip a candidate that lands where the vertex is (after a move to
  // the mean of the ideal points, the next search's first target): the old way measures it
  // (remeasure_current) and must reach the same positions, flips and statistics.
  for (const bool frontal : {false, true})
    for (const bool driver : {false, true})
      for (const bool blocked : {false, true}) {
        CAPTURE(frontal);
        CAPTURE(driver);
        CAPTURE(blocked);
        const Square base = square(0.012, frontal);
        OptimizeOptions oo;
        if (driver) oo.threshold = 0.75, oo.sacrifice_below = 0.7, oo.max_share_loss = 1e-4;  // face_smooth.cpp's del2d
        if (blocked) oo.block_min_triangles = 1000, oo.block_bad = 64;
        OptimizeOptions old = oo;
        old.remeasure_current = true;
        Square fast = base, slow = base;
        const OptimizeStats a = optimize_quality(fast.m, fast.fixed, oo);
        const OptimizeStats b = optimize_quality(slow.m, slow.fixed, old);
        CHECK(same_points_corners_twins(fast.m, slow.m));
        CHECK(fast.m.twin == slow.m.twin);
        CHECK(a.swaps == b.swaps);
        CHECK(a.moves == b.moves);
        CHECK(a.refused == b.refused);
        CHECK(a.compound_tried == b.compound_tried);
        CHECK(a.bad_after == b.bad_after);
        CHECK(a.min_after == b.min_after);
        CHECK(a.rounds == b.rounds);
        CHECK(a.blocks == b.blocks);
        CHECK(a.moves > 0);
        MESSAGE("frontal " << frontal << " driver " << driver << " blocked " << blocked << ": " << b.star_measures
                           << " -> " << a.star_measures << " star measures");
        CHECK(a.star_measures < b.star_measures);
      }
}

TEST_CASE("optimize_quality: compound changes only on flips that keep the valences near 6") {
  // front2d's unit square in a size ramp (0.01 at the bottom, +0.4 per unit up to 0.1, the
  // shore ramp's gradient): with the default compound_valence_rise some edges are not tried
  // (their flips pull the valences away from 6), so fewer compound changes are tried than
  // with the limit lifted; the share above 0.9 still does not fall.
  Square base;
  const Loop sq = testing::polygon_loop(base.m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.01, false);
  REQUIRE(testing::boundary_mesh(base.m, {sq}, &base.edges));
  base.fixed = base.m.num_vertices();
  RefineOptions ro;
  ro.size_at = [](std::span<const Vec2> pts, std::span<double> h) {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = std::min(0.01 + 0.4 * pts[i].y, 0.1);
  };
  REQUIRE(refine_front2d(base.m, ro).ok());
  smooth_laplacian(base.m, 1);
  const QualityStats before = mesh_quality(base.m);
  Square limited = base, all = base;
  OptimizeOptions every;
  every.compound_valence_rise = 1000;
  const OptimizeStats a = optimize_quality(limited.m, limited.fixed);
  const OptimizeStats b = optimize_quality(all.m, all.fixed, every);
  MESSAGE("compound changes tried " << b.compound_tried << " -> " << a.compound_tried << " ("
                                    << a.compound_valence_skipped << " edges left alone)");
  CHECK(a.compound_valence_skipped > 0);
  CHECK(b.compound_valence_skipped == 0);
  CHECK(a.compound_tried < b.compound_tried);
  std::vector<Vec2> fixed_xy(base.m.xy.begin(), base.m.xy.begin() + base.fixed);
  check_invariants(limited.m, limited.edges, fixed_xy);
  CHECK(mesh_quality(limited.m).share_rho_09 >= before.share_rho_09);
}

TEST_CASE("optimize_quality: the rounds end after a round that lifts few (min_round_gain)") {
  // A round must lift min_round_gain of its bad triangles for the next to run: at 1 (all
  // of them) one round only, at 0 the rounds go on while they change anything.
  const Square base = square(0.01, true);
  Square one = base, on = base;
  OptimizeOptions stop_early, go_on;
  stop_early.min_round_gain = 1;
  go_on.min_round_gain = 0;
  const OptimizeStats a = optimize_quality(one.m, one.fixed, stop_early);
  const OptimizeStats b = optimize_quality(on.m, on.fixed, go_on);
  MESSAGE("rounds " << b.rounds << " -> " << a.rounds << ", moves " << b.moves << " -> " << a.moves);
  CHECK(a.rounds == 1);
  CHECK(b.rounds > 1);
  CHECK(a.moves < b.moves);
}
