// mesh/mesh_stats: rho in 3D, edge-length ratios against a size, the summary and JSON.
#include "mesh/mesh_stats.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace sm;

namespace {

// Two triangles on the unit square's diagonal, plus an equilateral one far away, tilted
// out of the plane (rho does not depend on the orientation in space).
ModelMesh small_mesh() {
  ModelMesh m;
  const std::uint32_t a = m.add_node({0, 0, 0}), b = m.add_node({1, 0, 0}), c = m.add_node({1, 1, 0}),
                      d = m.add_node({0, 1, 0});
  const double s = std::sqrt(0.5);
  const std::uint32_t e = m.add_node({5, 0, 0}), f = m.add_node({5, s, s}),
                      g = m.add_node({5 + std::sqrt(0.75), 0.5 * s, 0.5 * s});
  SurfaceMesh sf;
  sf.tag = 1;
  sf.triangles = {{a, b, c}, {a, c, d}};
  m.surfaces[1] = sf;
  sf.tag = 2;
  sf.triangles = {{e, f, g}};
  m.surfaces[2] = sf;
  return m;
}

}  // namespace

TEST_CASE("mesh_stats: counts, quality shares and length ratios") {
  ModelMesh m = small_mesh();
  m.add_node({9, 9, 9});   // a model point no triangle uses: not counted
  const double right = 2 * (2 - std::sqrt(2.0)) / std::sqrt(2.0);
  MeshStats s = mesh_stats(m);
  CHECK(s.nodes == 7);
  CHECK(s.triangles == 3);
  CHECK_FALSE(s.has_sizes);
  CHECK(s.min_rho == doctest::Approx(right));
  CHECK(s.mean_rho == doctest::Approx((2 * right + 1) / 3));
  CHECK(s.share_rho_09 == doctest::Approx(1.0 / 3));
  // Size 1 everywhere: 5 square edges + 3 equilateral edges of length 1, one diagonal of
  // sqrt 2 (shared, counted once): ratios {1 x 7, 1.414...}.
  s = mesh_stats(m, [](std::span<const Vec3>, std::span<double> h) { std::fill(h.begin(), h.end(), 1.0); });
  CHECK(s.edges == 8);
  CHECK(s.len_median == doctest::Approx(1));
  CHECK(s.len_p05 == doctest::Approx(1));
  CHECK(s.len_p95 > 1.1);
  CHECK(s.share_len_07_14 == doctest::Approx(7.0 / 8));
  s.stages = {{"1D", 0.25}, {"2D \"refine\"", 0.5}};
  const std::string text = format_stats(s);
  CHECK(text.find("7 nodes, 3 triangles") != std::string::npos);
  CHECK(text.find("total 0.750 s") != std::string::npos);
  const std::string json = stats_json(s);
  CHECK(json.find("\"nodes\": 7") != std::string::npos);
  CHECK(json.find("\"edges\": 8") != std::string::npos);
  CHECK(json.find("\"2D \\\"refine\\\"\": 0.5") != std::string::npos);
  CHECK(json.front() == '{');
}

TEST_CASE("mesh_stats: an empty mesh") {
  const MeshStats s = mesh_stats(ModelMesh{});
  CHECK(s.triangles == 0);
  CHECK(s.min_rho == 0);
  CHECK(stats_json(s).find("\"triangles\": 0") != std::string::npos);
}

TEST_CASE("mesh_stats: a target size per surface, shared edges measured once by the first") {
  ModelMesh m = small_mesh();
  // Surface 3 shares the square's edge b-c with surface 1 and adds one triangle.
  const std::uint32_t x = m.add_node({2, 0.5, 0});
  SurfaceMesh sf;
  sf.tag = 3;
  sf.triangles = {{1, x, 2}};
  m.surfaces[3] = sf;
  const auto uniform = [](double size) {
    return [size](std::span<const Vec3>, std::span<double> h) { std::fill(h.begin(), h.end(), size); };
  };
  // Surface 1: size 1; surface 2: size 0.5 (its three unit edges read 2); surface 3: size
  // 1000, but its edge b-c belongs to surface 1 first (ratio 1), so only its two new edges
  // (length sqrt(1.25)) read ~0.001.
  const MeshStats s = mesh_stats(m, std::vector<SurfaceSize>{{3, uniform(1000)}, {1, uniform(1)}, {2, uniform(0.5)}});
  REQUIRE(s.has_sizes);
  CHECK(s.edges == 10);
  // Sorted ratios: 0.0011 x 2, 1 x 4, 1.414, 2 x 3.
  CHECK(s.len_median == doctest::Approx(1));
  CHECK(s.len_p05 == doctest::Approx(0.001 * std::sqrt(1.25)));
  CHECK(s.len_p95 == doctest::Approx(2));
  CHECK(s.share_len_07_14 == doctest::Approx(4.0 / 10));
  // A surface without an entry is left out of the ratios but not of the quality.
  const MeshStats part = mesh_stats(m, std::vector<SurfaceSize>{{1, uniform(1)}});
  CHECK(part.triangles == 4);
  CHECK(part.edges == 5);
  CHECK(part.len_median == doctest::Approx(1));
  const MeshStats none = mesh_stats(m, std::vector<SurfaceSize>{});
  CHECK_FALSE(none.has_sizes);
}

TEST_CASE("curve_stats: the 1D summary of -1 (curves with edges, nodes, shortest and longest edge)") {
  ModelMesh m;
  for (double x : {0.0, 1.0, 3.0, 6.0}) m.add_node({x, 0, 0});
  m.add_node({0, 2, 0});
  m.add_node({9, 9, 9});                 // on no curve: not counted
  CurveMesh a;
  a.tag = 1, a.nodes = {0, 1, 2, 3};   // edges 1, 2, 3
  CurveMesh b;
  b.tag = 2, b.nodes = {0, 4};         // edge 2
  CurveMesh none;
  none.tag = 3;                          // no mesh: not counted
  m.curves[1] = a, m.curves[2] = b, m.curves[3] = none;
  const CurveStats s = curve_stats(m);
  CHECK(s.curves == 2);
  CHECK(s.nodes == 5);
  CHECK(s.edges == 4);
  CHECK(s.shortest == 1.0);
  CHECK(s.longest == 3.0);
  CHECK(format_curve_stats(s) == "Mesh: 5 nodes, 4 line elements on 2 curves; edges from 1 to 3 (model units)\n");
}

TEST_CASE("curve_stats: on the model's sphere the edges are great-circle arcs, in km; JSON for --stats") {
  const double r = 6371e3, pi = std::acos(-1.0);
  ModelMesh m;
  // A quarter of the equator in 2 edges of 45 degrees, and one of 10 degrees along a meridian.
  for (double deg : {0.0, 45.0, 90.0}) m.add_node({r * std::cos(deg * pi / 180), r * std::sin(deg * pi / 180), 0});
  m.add_node({r * std::cos(10 * pi / 180), 0, r * std::sin(10 * pi / 180)});
  CurveMesh a;
  a.tag = 1, a.nodes = {0, 1, 2};
  CurveMesh b;
  b.tag = 2, b.nodes = {0, 3};
  m.curves[1] = a, m.curves[2] = b;
  const CurveStats s = curve_stats(m, Vec3{0, 0, 0}, r);
  CHECK(s.on_sphere);
  CHECK(s.shortest == doctest::Approx(r * 10 * pi / 180).epsilon(1e-12));
  CHECK(s.longest == doctest::Approx(r * 45 * pi / 180).epsilon(1e-12));
  // 5003.8 km along the sphere where the chord is 4876 km.
  CHECK(format_curve_stats(s) ==
        "Mesh: 4 nodes, 3 line elements on 2 curves; edges from 1112 km to 5004 km on the sphere\n");
  const std::string json = curve_stats_json(s, {{"1D", 0.5}});
  CHECK(json.find("\"nodes\": 4, \"line_elements\": 3, \"curves\": 2, \"edge_min\": ") == 1);
  CHECK(json.find("\"edge_units\": \"m\", \"stages\": {\"1D\": 0.5}}") != std::string::npos);
  // A node off the sphere: chords in model units for every edge.
  m.add_node({0, 0, 0});
  CurveMesh c;
  c.tag = 3, c.nodes = {3, 4};
  m.curves[3] = c;
  const CurveStats mixed = curve_stats(m, Vec3{0, 0, 0}, r);
  CHECK_FALSE(mixed.on_sphere);
  CHECK(mixed.longest == doctest::Approx(r));
  CHECK(format_curve_stats(mixed).find("(model units)") != std::string::npos);
}

TEST_CASE("mesh_stats: the length quantiles are those of the sorted ratios, for 3 to 399 edges") {
  // A fan of k triangles around node 0 with rim nodes at varied distances: 2k + 1 distinct
  // edges of distinct lengths (size 1: the ratios are the lengths). Each quantile is
  // checked to the last bit against the sorted lengths, linear between the two order
  // statistics around q (n - 1), for every count (the selections nest on the median).
  for (int k : {1, 2, 3, 4, 5, 7, 10, 19, 20, 21, 64, 199}) {
    CAPTURE(k);
    ModelMesh m;
    m.add_node({0, 0, 0});
    for (int i = 0; i <= k; ++i) {
      const double a = 3.0 * i / k, r = 1 + 0.37 * std::sin(1.3 * i + 0.2 * i * i);
      m.add_node({r * std::cos(a), r * std::sin(a), 0});
    }
    SurfaceMesh sf;
    sf.tag = 1;
    for (std::uint32_t i = 1; i <= static_cast<std::uint32_t>(k); ++i) sf.triangles.push_back({0, i, i + 1});
    m.surfaces[1] = sf;
    std::vector<double> len;
    for (std::uint32_t i = 1; i <= static_cast<std::uint32_t>(k) + 1; ++i) len.push_back(norm(m.nodes[i].xyz));
    for (std::uint32_t i = 1; i <= static_cast<std::uint32_t>(k); ++i)
      len.push_back(norm(m.nodes[i + 1].xyz - m.nodes[i].xyz));
    std::sort(len.begin(), len.end());
    const auto expected = [&](double q) {
      const double pos = q * static_cast<double>(len.size() - 1);
      const std::size_t i = static_cast<std::size_t>(pos);
      const double f = pos - static_cast<double>(i);
      return i + 1 >= len.size() ? len[i] : len[i] * (1 - f) + len[i + 1] * f;
    };
    const MeshStats s =
        mesh_stats(m, [](std::span<const Vec3>, std::span<double> h) { std::fill(h.begin(), h.end(), 1.0); });
    REQUIRE(s.edges == len.size());
    CHECK(s.len_median == expected(0.5));
    CHECK(s.len_p05 == expected(0.05));
    CHECK(s.len_p95 == expected(0.95));
  }
}
