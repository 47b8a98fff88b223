// flip_valence_rise against the valences counted again after the flip, on a front2d square
// with a hole: every inner edge of a free quad, both ways round.
#include <doctest/doctest.h>

#include <vector>

#include "exact/predicates.h"
#include "mesh/frontal.h"
#include "mesh/modify/flip_valence.h"
#include "mesh/refine.h"
#include "testing_domains.h"

using namespace sm;

namespace {

int energy(const TriangleStore& m, const VertexId (&vs)[4], std::uint32_t fixed) {
  int e = 0;
  for (const VertexId v : vs) {
    const int k = free_valence(m, v, fixed);
    if (k >= 0) e += (k - 6) * (k - 6);
  }
  return e;
}

}  // namespace

TEST_CASE("flip_valence_rise: the change of sum (valence - 6)^2 that the flip makes") {
  TriangleStore m;
  const Loop sq = testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.05, false);
  const Loop hole = testing::circle_loop(m, {0.4, 0.6}, 0.15, 0.05, true);
  REQUIRE(testing::boundary_mesh(m, {sq, hole}));
  const std::uint32_t fixed = m.num_vertices();
  RefineOptions opt;
  opt.size = 0.05;
  REQUIRE(refine_front2d(m, opt).ok());
  int checked = 0, lowering = 0, raising = 0, boundary_left_out = 0;
  for (std::uint32_t s = 0; s < m.corner.size() && checked < 200; ++s) {
    const Side side{s};
    if (!m.alive(tri_of(side)) || !m.twin[s].valid() || m.constrained(side)) continue;
    const Side o = m.twin[s];
    const VertexId vs[4] = {m.org(side), m.dest(side), m.apex(side), m.apex(o)};
    // The flip must keep a valid triangulation: a convex quad.
    if (orient2d(m.pos(vs[2]), m.pos(vs[0]), m.pos(vs[3])) != Sign::Positive ||
        orient2d(m.pos(vs[3]), m.pos(vs[1]), m.pos(vs[2])) != Sign::Positive)
      continue;
    int free_corners = 0;
    for (const VertexId v : vs) free_corners += free_valence(m, v, fixed) >= 0;
    boundary_left_out += free_corners < 4;
    const int predicted = flip_valence_rise(m, side, fixed);
    const int before = energy(m, vs, fixed);
    const Side n = m.flip(side);
    const int after = energy(m, vs, fixed);
    m.flip(n);
    CHECK(predicted == after - before);
    lowering += predicted < 0, raising += predicted > 0;
    ++checked;
  }
  MESSAGE(checked << " flips checked: " << lowering << " lower the energy, " << raising << " raise it, "
                  << boundary_left_out << " with a boundary corner left out");
  CHECK(checked == 200);
  CHECK(lowering > 0);
  CHECK(raising > 0);
  CHECK(boundary_left_out > 0);
}
