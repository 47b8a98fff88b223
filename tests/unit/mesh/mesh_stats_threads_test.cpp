// mesh/mesh_stats on several threads: the qualities and the sizes at the edge midpoints
// are computed in chunks of fixed bounds, so every figure is the same for any count.
#include "mesh/mesh_stats.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

namespace {

// A jittered n x n grid of right triangles split into two surfaces (tags 3 and 8) that
// share the column i = n / 2: more triangles and edges than one chunk of each.
sm::ModelMesh threads_stats_grid(int n) {
  sm::ModelMesh m;
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      m.add_node({i + 0.3 * std::sin(1.7 * i + 2.3 * j), j + 0.3 * std::cos(2.1 * i - 1.3 * j), 0.01 * i * j});
  sm::SurfaceMesh a, b;
  a.tag = 3;
  b.tag = 8;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      sm::SurfaceMesh& s = i < n / 2 ? a : b;
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  m.surfaces[3] = a;
  m.surfaces[8] = b;
  return m;
}

}  // namespace

TEST_CASE("mesh_stats threads: the same figures to the last bit for 1, 2, 3 and 6 threads") {
  const sm::ModelMesh m = threads_stats_grid(160);
  std::vector<sm::SurfaceSize> sizes;
  sizes.push_back({3, [](std::span<const sm::Vec3> x, std::span<double> h) {
                     for (std::size_t i = 0; i < x.size(); ++i) h[i] = 0.8 + 0.4 * std::sin(0.1 * x[i].x);
                   }});
  sizes.push_back({8, [](std::span<const sm::Vec3> x, std::span<double> h) {
                     for (std::size_t i = 0; i < x.size(); ++i) h[i] = 1.1 + 0.2 * std::cos(0.07 * x[i].y);
                   }});
  const sm::MeshStats one = sm::mesh_stats(m, sizes, 1);
  REQUIRE(one.triangles == 2u * 160 * 160);
  REQUIRE(one.has_sizes);
  CHECK(one.edges > 70000);
  CHECK(one.min_rho < one.mean_rho);
  for (int threads : {2, 3, 6}) {
    CAPTURE(threads);
    const sm::MeshStats s = sm::mesh_stats(m, sizes, threads);
    CHECK(s.nodes == one.nodes);
    CHECK(s.edges == one.edges);
    CHECK(s.min_rho == one.min_rho);
    CHECK(s.min_rho_surface == one.min_rho_surface);
    CHECK(s.min_rho_at == one.min_rho_at);
    CHECK(s.mean_rho == one.mean_rho);
    CHECK(s.share_rho_09 == one.share_rho_09);
    CHECK(s.len_median == one.len_median);
    CHECK(s.len_p05 == one.len_p05);
    CHECK(s.len_p95 == one.len_p95);
    CHECK(s.share_len_07_14 == one.share_len_07_14);
    CHECK(sm::stats_json(s) == sm::stats_json(one));   // every figure, as --stats writes it
  }
}
