// Coastline kernel figures on real data: GSHHG world intermediate shorelines
// (features >= 100 km2) in the South-Pole stereographic plane, resampled at
// 10 km: Delaunay points/s, edge recovery time, and the full self-intersection
// repair loop (paper section 3.2). Usage: bench_mesh_coast [file] [step_km]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../unit/mesh/testing_coast.h"
#include "mesh/cdt.h"
#include "mesh/delaunay.h"

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : "world_i_A100.txt";
  const double step = argc > 2 ? std::atof(argv[2]) : 10.0;
  auto t0 = std::chrono::steady_clock::now();
  const auto rings = sm::testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/" + file);
  std::vector<sm::testing::RingCurve> curves;
  for (const auto& r : rings) curves.emplace_back(r);
  sm::BoundaryProblem p = sm::testing::coast_problem(curves, step);
  std::printf("%s at %g km: %zu rings, %zu points (read + resample %.3f s)\n", file.c_str(), step, rings.size(),
              p.points.size(), since(t0));
  // One Delaunay + one recovery pass, timed apart.
  sm::TriangleStore m;
  m.xy = p.points;
  t0 = std::chrono::steady_clock::now();
  const auto dr = sm::delaunay(m);
  const double td = since(t0);
  if (!dr.ok()) return std::fprintf(stderr, "delaunay: %s\n", dr.error.c_str()), 1;
  std::vector<sm::Edge> edges;
  for (const auto& cv : p.curves)
    for (std::size_t k = 0; k + 1 < cv.pts.size(); ++k)
      edges.push_back({sm::VertexId{cv.pts[k]}, sm::VertexId{cv.pts[k + 1]}});
  t0 = std::chrono::steady_clock::now();
  const auto rr = sm::recover_edges(m, sm::PlanarGeometry{&m.xy}, edges);
  const double tr = since(t0);
  std::printf("delaunay      %9.4f s  %12.0f points/s\n", td, p.points.size() / td);
  std::printf("edge recovery %9.4f s  %zu edges, %llu swaps, %zu crossings found\n", tr, edges.size(),
              static_cast<unsigned long long>(rr.stats.flips), rr.crossings.size());
  // The full repair loop on the same input.
  const auto split = [&](std::uint32_t c, double t) { return curves[c].at(t); };
  t0 = std::chrono::steady_clock::now();
  const auto br = sm::recover_boundary(p, split, {});
  const double tb = since(t0);
  if (!br.ok()) return std::fprintf(stderr, "repair: %s\n", br.error.message.c_str()), 1;
  std::printf("repair loop   %9.4f s  %u rounds, %u splits, %zu final points\n", tb, br.rounds, br.splits,
              p.points.size());
  return 0;
}
