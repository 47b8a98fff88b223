// optimize_quality in blocks (optimize_blocks.h): the same bytes and stats on 1, 2 and 3
// threads on a face cut into several blocks, valid, constraints kept, the worst rho raised
// as far as the serial pass raises it and the share above 0.9 not lower than the input's.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "mesh/check.h"
#include "mesh/modify/optimize.h"
#include "mesh/modify/smooth.h"
#include "mesh/refine.h"
#include "mesh/store_undo.h"
#include "testing_domains.h"

using namespace sm;

namespace {

bool same_store_bytes(const TriangleStore& a, const TriangleStore& b) {
  return a.xy.size() == b.xy.size() && std::memcmp(a.xy.data(), b.xy.data(), a.xy.size() * sizeof(Vec2)) == 0 &&
         a.corner == b.corner && a.twin == b.twin && a.side_flags == b.side_flags && a.out_side == b.out_side;
}

double share_above(const TriangleStore& m, double bar) {
  std::size_t good = 0;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(TriId{t}))
      good += rho_ccw(m.pos(m.vertex(TriId{t}, 0)), m.pos(m.vertex(TriId{t}, 1)), m.pos(m.vertex(TriId{t}, 2))) > bar;
  return double(good) / m.num_triangles();
}

struct Face {
  TriangleStore m;
  std::vector<Edge> edges;
  std::uint32_t fixed = 0;
};

// The unit square with two holes at size h by del2d, one Laplacian pass (the face driver's).
Face holed_square(double h) {
  Face f;
  const Loop sq = testing::polygon_loop(f.m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  const Loop a = testing::circle_loop(f.m, {0.3, 0.6}, 0.12, h, true);
  const Loop b = testing::circle_loop(f.m, {0.7, 0.35}, 0.1, h, true);
  REQUIRE(testing::boundary_mesh(f.m, {sq, a, b}, &f.edges));
  f.fixed = f.m.num_vertices();
  RefineOptions opt;
  opt.size = h;
  REQUIRE(refine_del2d(f.m, opt).ok());
  smooth_laplacian(f.m, 1);
  return f;
}

// The face driver's del2d settings, blocked from a small face on: blocks of 64 bad triangles.
OptimizeOptions blocked_options(int threads) {
  OptimizeOptions oo;
  oo.threshold = 0.75, oo.sacrifice_below = 0.7, oo.max_share_loss = 1e-4;
  oo.threads = threads;
  oo.block_min_triangles = 1;
  oo.block_bad = 64;
  return oo;
}

}  // namespace

TEST_CASE("optimize_quality in blocks: the same bytes and stats on 1, 2 and 3 threads") {
  const Face base = holed_square(0.006);
  std::vector<TriangleStore> out;
  std::vector<OptimizeStats> stats;
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    Face f = base;
    stats.push_back(optimize_quality(f.m, f.fixed, blocked_options(threads)));
    REQUIRE(check_topology(f.m).ok());
    REQUIRE(check_constraints(f.m, f.edges).ok());
    for (std::uint32_t v = 0; v < base.fixed; ++v) REQUIRE(f.m.xy[v] == base.m.xy[v]);
    out.push_back(std::move(f.m));
  }
  // Several blocks, so that several run at once and their borders matter.
  CHECK(stats[0].blocks >= 4);
  for (std::size_t i = 1; i < out.size(); ++i) {
    CAPTURE(i);
    CHECK(same_store_bytes(out[0], out[i]));
    CHECK(stats[i].blocks == stats[0].blocks);
    CHECK(stats[i].swaps == stats[0].swaps);
    CHECK(stats[i].moves == stats[0].moves);
    CHECK(stats[i].bad_after == stats[0].bad_after);
    CHECK(stats[i].min_after == stats[0].min_after);
  }
}

TEST_CASE("optimize_quality in blocks: as good as the serial pass, the share above 0.9 kept") {
  const Face base = holed_square(0.006);
  Face serial = base, blocked = base;
  OptimizeOptions so = blocked_options(1);
  so.block_min_triangles = 0;
  const OptimizeStats ss = optimize_quality(serial.m, serial.fixed, so);
  const OptimizeStats bs = optimize_quality(blocked.m, blocked.fixed, blocked_options(2));
  CHECK(ss.blocks == 0);
  CHECK(bs.blocks >= 4);
  CHECK(bs.bad_before == ss.bad_before);
  CHECK(bs.min_before == ss.min_before);
  CHECK(bs.min_after > bs.min_before);
  CHECK(bs.min_after >= ss.min_after - 0.02);
  CHECK(bs.bad_after <= ss.bad_after + ss.bad_after / 20);
  CHECK(share_above(blocked.m, 0.9) >= share_above(base.m, 0.9) - 1e-4);
  MESSAGE("serial: min ", ss.min_after, " bad ", ss.bad_after, "; blocked: min ", bs.min_after, " bad ", bs.bad_after,
          " blocks ", bs.blocks, " of ", bs.bad_before, " bad");
}

TEST_CASE("optimize_quality in blocks under an undo journal: the same bytes, and put back exactly") {
  // The quality floor's quality pass runs with the floor's journal attached (face_floor.cpp):
  // the blocks save what they will write before the threads start.
  const Face base = holed_square(0.006);
  Face plain = base;
  const OptimizeStats ps = optimize_quality(plain.m, plain.fixed, blocked_options(2));
  REQUIRE(ps.blocks >= 4);
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    Face f = base;
    StoreUndo undo(f.m);
    const OptimizeStats js = optimize_quality(f.m, f.fixed, blocked_options(threads));
    CHECK(js.blocks == ps.blocks);
    CHECK(same_store_bytes(f.m, plain.m));
    undo.restore(f.m);   // asserts the fingerprint of the store at the start
    CHECK(same_store_bytes(f.m, base.m));
  }
}
