#include "mesh/time_step.h"

#include <cmath>
#include <numbers>

#include <doctest/doctest.h>

#include "mesh/mesh_stats.h"

using namespace sm;

namespace {

// Two triangles of a 100 m x 50 m rectangle split along its diagonal, and a third,
// sliver-free, far away: (0,0) (100,0) (100,50) | (0,0) (100,50) (0,50) | (1000,0)
// (1030,0) (1000,40).
ModelMesh ts_mesh() {
  ModelMesh m;
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{100, 0, 0}, Vec3{100, 50, 0}, Vec3{0, 50, 0}, Vec3{1000, 0, 0},
                 Vec3{1030, 0, 0}, Vec3{1000, 40, 0}})
    m.add_node(p);
  m.surfaces[1].tag = 1;
  m.surfaces[1].triangles = {{0, 1, 2}, {0, 2, 3}};
  m.surfaces[2].tag = 2;
  m.surfaces[2].triangles = {{4, 5, 6}};
  return m;
}

}  // namespace

TEST_CASE("time step: min over triangles of shortest edge / sqrt(g H), H the deepest node") {
  const ModelMesh m = ts_mesh();
  // Depths: 10 m at the left nodes, 40 m at (100,50), 1 m on the far triangle.
  const std::vector<double> depth = {10, 10, 40, 10, 1, 1, 1};
  const TimeStep t = courant_time_step(m, depth);
  REQUIRE(t.valid);
  // Triangle 1: shortest edge 50 m, H = 40: 50 / sqrt(9.81 * 40) = 2.5240 s. Triangle 2:
  // shortest 50, H = 40 too. Triangle 3: shortest 30 m, H = 1: 9.578 s.
  CHECK(t.dt == doctest::Approx(50 / std::sqrt(9.81 * 40)));
  CHECK(t.surface == 1);
  CHECK(t.edge == doctest::Approx(50));
  CHECK(t.depth == doctest::Approx(40));
  CHECK(t.where.x == doctest::Approx(200.0 / 3));   // the first of the two equal ones
  CHECK_FALSE(t.has_lonlat);
  // Deeper far triangle: it limits.
  const std::vector<double> deep = {10, 10, 40, 10, 1, 1, 400};
  CHECK(courant_time_step(m, deep).dt == doctest::Approx(30 / std::sqrt(9.81 * 400)));
  CHECK(courant_time_step(m, deep).surface == 2);
  // Dry triangles (no node deeper than 0) are skipped, unless MinDepth raises them.
  const std::vector<double> dry = {0, -5, 0, 0, 1, 1, 1};
  CHECK(courant_time_step(m, dry).dt == doctest::Approx(30 / std::sqrt(9.81)));
  TimeStepOptions o;
  o.min_depth = 2;
  // The far triangle too: H = 2, 30 / sqrt(9.81 * 2) is below 50 / sqrt(9.81 * 2).
  CHECK(courant_time_step(m, dry, o).dt == doctest::Approx(30 / std::sqrt(9.81 * 2)));
  CHECK(courant_time_step(m, dry, o).depth == doctest::Approx(2));
  CHECK_FALSE(courant_time_step(m, std::vector<double>(7, 0.0)).valid);
}

TEST_CASE("time step: great-circle edges and lon/lat on a sphere, in the summary and JSON") {
  const double r = 6371e3, deg = std::numbers::pi / 180;
  auto at = [&](double lon, double lat) {
    return Vec3{r * std::cos(lat * deg) * std::cos(lon * deg), r * std::cos(lat * deg) * std::sin(lon * deg),
                r * std::sin(lat * deg)};
  };
  ModelMesh m;
  m.add_node(at(10, 0));
  m.add_node(at(11, 0));
  m.add_node(at(10, 1));
  m.surfaces[1].triangles = {{0, 1, 2}};
  TimeStepOptions o;
  o.radius = r;
  const TimeStep t = courant_time_step(m, std::vector<double>{4000, 4000, 4000}, o);
  REQUIRE(t.valid);
  // Both legs are one degree of a great circle: 111,194.9 m.
  CHECK(t.edge == doctest::Approx(r * deg).epsilon(1e-12));
  CHECK(t.dt == doctest::Approx(r * deg / std::sqrt(9.81 * 4000)));
  REQUIRE(t.has_lonlat);
  CHECK(t.lon == doctest::Approx(31.0 / 3).epsilon(1e-3));
  CHECK(t.lat == doctest::Approx(1.0 / 3).epsilon(1e-2));
  MeshStats st = mesh_stats(m);
  st.time_step = t;
  CHECK(format_stats(st).find("Time step (Courant 1): dt 561.3 s at lon 10.3") != std::string::npos);
  CHECK(stats_json(st).find("\"dt\": ") != std::string::npos);
  CHECK(stats_json(st).find("\"dt_lon\": ") != std::string::npos);
}
