// Real data: the GSHHG world shorelines in the paper's stereographic plane,
// every coastline edge recovered (with repairs where chords cross).
#include <doctest/doctest.h>

#include "mesh/check.h"
#include "testing_coast.h"

using namespace sm;

namespace {

void run_world(const char* file, double step_km) {
  const auto rings = testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/" + file);
  REQUIRE(rings.size() > 100);
  std::vector<testing::RingCurve> curves;
  for (const auto& r : rings) curves.emplace_back(r);
  BoundaryProblem p = testing::coast_problem(curves, step_km);
  const std::size_t n0 = p.points.size();
  const auto split = [&](std::uint32_t c, double t) { return curves[c].at(t); };
  BoundaryOptions opt;
  opt.tolerance = 1e-9;  // ~6 mm on the unit sphere's plane near the equator
  const BoundaryResult r = recover_boundary(p, split, opt);
  INFO(std::string(file), " step ", step_km, ": ", r.error.message);
  REQUIRE(r.ok());
  MESSAGE(std::string(file) << " step " << step_km << " km: " << n0 << " points, " << r.edges.size() << " edges, "
                << r.rounds << " rounds, " << r.splits << " splits");
  REQUIRE(check_topology(r.mesh).ok());
  REQUIRE(check_constraints(r.mesh, r.edges).ok());
  REQUIRE(check_delaunay(r.mesh, PlanarGeometry{&r.mesh.xy}, true).ok());
  // Keep the ocean: Antarctica's ice front (the ring round the South Pole,
  // hence the largest loop in this plane) is the outer loop, every other
  // ring an island.
  const std::vector<Loop> loops = testing::ocean_loops(p, rings);
  TriangleStore m = r.mesh;
  const auto d = remove_outside(m, PlanarGeometry{&m.xy}, loops);
  INFO(d.error);
  REQUIRE(d.ok());
  CHECK(d.removed > 0);
  CHECK(m.num_triangles() > 0);
  CHECK(check_topology(m).ok());
}

}  // namespace

TEST_CASE("coast recovery: world crude shorelines, raw vertices") { run_world("world_c.txt", 0); }

TEST_CASE("coast recovery: world low shorelines resampled at 30 km") { run_world("world_l.txt", 30); }

TEST_CASE("coast recovery: a genuinely self-intersecting real coastline fails, located") {
  // GSHHG low, raw vertices: the Antarctic ice-front ring (segment 6) crosses
  // itself near lon 162.4, lat -76.1 (its edges 32-33 and 34-35 intersect in
  // lon/lat: a simplification defect of the source data).
  const auto rings = testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/world_l.txt");
  std::vector<testing::RingCurve> curves;
  for (const auto& r : rings) curves.emplace_back(r);
  BoundaryProblem p = testing::coast_problem(curves, 0);
  BoundaryOptions opt;
  opt.tolerance = 1e-9;
  const BoundaryResult r = recover_boundary(p, [&](std::uint32_t c, double t) { return curves[c].at(t); }, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == BoundaryErrorKind::Intersection);
  CHECK(r.error.curve_a == 6);
  CHECK(r.error.curve_b == 6);
  CHECK(rings[5].wraps_pole);
  // Back to lon/lat from the South-Pole stereographic plane.
  const double rho2 = norm2(r.error.where);
  const double lat = std::asin((1 - rho2) / (1 + rho2)) * 180 / M_PI;
  const double lon = std::atan2(r.error.where.y, r.error.where.x) * 180 / M_PI;
  MESSAGE(r.error.message << " = lon " << lon << ", lat " << lat);
  CHECK(std::fabs(lon - 162.4) < 0.3);
  CHECK(std::fabs(lat + 76.1) < 0.2);
}
