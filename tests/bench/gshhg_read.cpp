// Reading a binned GSHHG file alone (no import): rings, points and wall time, for
// /usr/bin/time -v to give the peak memory of the read (docs/benchmarks_scale.md).
//   bench_gshhg_read [c|l|i|h|f|PATH] [min_area_km2] [west east south north]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "coast/read_gshhg_binned.h"

int main(int argc, char** argv) {
  using namespace sm::coast;
  const std::string arg = argc > 1 ? argv[1] : "f";
  const std::string path = is_gshhg_resolution(arg) ? gshhg_binned_file(arg[0]) : arg;
  GshhgBinnedOptions o;
  if (argc > 2) o.min_area_km2 = std::atof(argv[2]);
  if (argc > 6) o.region = LonLatBox{std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5]), std::atof(argv[6])};
  const auto t0 = std::chrono::steady_clock::now();
  auto c = read_gshhg_binned(path, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!c) {
    std::fprintf(stderr, "%s\n", c.error().to_string().c_str());
    return 1;
  }
  std::size_t points = 0, wraps = 0;
  for (const Ring& r : c->rings) points += r.pts.size(), wraps += r.wraps_pole;
  std::printf("%s: %zu rings, %zu points, %zu round the pole, read in %.3f s\n", path.c_str(), c->rings.size(), points,
              wraps, s);
  return 0;
}
