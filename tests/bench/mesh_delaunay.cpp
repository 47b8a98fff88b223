// Delaunay points per second for uniform random points in the unit square
// (1e5, 1e6, 4e6 points; one core). Best of `reps` runs, wall clock and the
// thread's CPU time (the latter is the fair figure on a loaded machine).
// Usage: bench_mesh_delaunay [reps]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>

#include "mesh/check.h"
#include "mesh/delaunay.h"

namespace {

double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 3;
  std::printf("%9s %9s %12s %9s %12s %8s %10s\n", "points", "wall s", "points/s", "cpu s", "points/s(cpu)", "walk/pt",
              "exact/call");
  for (std::uint32_t n : {100000u, 1000000u, 4000000u}) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> U(0, 1);
    std::vector<sm::Vec2> pts(n);
    for (auto& p : pts) p = {U(rng), U(rng)};
    double best_wall = 1e30, best_cpu = 1e30;
    sm::DelaunayResult r;
    sm::TriangleStore m;
    for (int k = 0; k < reps; ++k) {
      m.clear();
      m.xy = pts;
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = cpu_seconds();
      r = sm::delaunay(m);
      const double c1 = cpu_seconds();
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!r.ok()) {
        std::fprintf(stderr, "delaunay failed: %s\n", r.error.c_str());
        return 1;
      }
      best_wall = std::min(best_wall, s);
      best_cpu = std::min(best_cpu, c1 - c0);
    }
    const auto& ps = r.stats.predicates;
    std::printf("%9u %9.3f %12.0f %9.3f %12.0f %8.2f %10.2e\n", n, best_wall, n / best_wall, best_cpu, n / best_cpu,
                double(r.stats.walk_steps) / n,
                double(ps.orient2d_exact + ps.incircle_exact) / double(ps.orient2d_calls + ps.incircle_calls));
    if (n == 100000u && !sm::check_delaunay(m, sm::PlanarGeometry{&m.xy}).ok()) return 1;
  }
  return 0;
}
