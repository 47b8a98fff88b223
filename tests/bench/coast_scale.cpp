// Benchmark: the coastline import of one large shoreline file, step by step, with the
// process's peak memory after each (tests/bench/run.sh --scale runs it on the full
// GSHHG). A constant accuracy gamma, so that the figures are those of the import alone,
// with the options examples/world_ocean.geo sets (the strait merges, the narrow water
// closed up to gamma, the passages between two waters kept): the two steps that take most
// of the import at 3 km, which the "repair" step's row holds; the import's own account of
// that step (its parts: deviation, repair, straits, orient, passages) follows in rows of
// their own.
//   bench_coast_scale FILE GAMMA_M|- [THREADS] [--write-gshhs OUT.b]
// FILE is GMT lon/lat text, a GSHHS binary when it ends in ".b", or one of GMT's binned
// GSHHG files when it ends in ".nc" (/usr/share/gmt-gshhg/binned_GSHHS_f.nc: the whole
// world at full resolution). --write-gshhs stores what was read as a GSHHS 2.x binary; a GAMMA of
// "-" stops after reading (and writing).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "base/progress.h"
#include "coast/import.h"
#include "coast/read_gshhg_binned.h"
#include "coast/read_gshhs.h"
#include "coast/read_lonlat_text.h"
#include "coast/write_gshhs.h"

using namespace sm;
using namespace sm::coast;

namespace {

using Clock = std::chrono::steady_clock;

double peak_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

double cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto s = [](timeval t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

struct Row {
  std::string name;
  double wall, cpu, peak;
};

// Records the wall and CPU time of each of build_coast_model's steps (its progress units).
class StepTimer final : public Progress {
 public:
  explicit StepTimer(std::vector<Row>& rows) : rows_(rows) {}
  void begin(std::string_view, std::uint64_t) override { mark(); }
  void update(std::uint64_t done) override {
    static const char* const names[] = {"levels",    "cleaning", "clipping", "coarsening",
                                        "curves",    "repair",   "surfaces", "output"};
    const std::size_t i = done >= 1 && done <= 8 ? done - 1 : 8;
    row(i < 8 ? names[i] : "?");
  }
  void end() override {}
  void mark() {
    t_ = Clock::now();
    c_ = cpu_s();
  }
  void row(const char* name) {
    const auto now = Clock::now();
    const double c = cpu_s();
    rows_.push_back({name, std::chrono::duration<double>(now - t_).count(), c - c_, peak_mb()});
    t_ = now;
    c_ = c;
  }

 private:
  std::vector<Row>& rows_;
  Clock::time_point t_;
  double c_ = 0;
};

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string write_to;
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--write-gshhs") {
      write_to = args[i + 1];
      args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 2);
      break;
    }
  if (args.size() < 2) {
    std::fprintf(stderr, "usage: bench_coast_scale FILE GAMMA_M|- [THREADS] [--write-gshhs OUT.b]\n");
    return 2;
  }
  const std::string file = args[0];
  const double gamma = std::atof(args[1].c_str());
  const int threads = args.size() > 2 ? std::atoi(args[2].c_str()) : 1;
  std::vector<Row> rows;
  StepTimer timer(rows);
  timer.mark();
  auto data = ends_with(file, ".b")    ? read_gshhs(file)
              : ends_with(file, ".nc") ? read_gshhg_binned(file)
                                       : read_lonlat_text(file);
  if (!data) {
    std::fprintf(stderr, "%s\n", data.error().to_string().c_str());
    return 1;
  }
  timer.row("read");
  std::size_t points = 0;
  for (const Ring& r : data->rings) points += r.pts.size();
  if (!write_to.empty()) {
    auto w = write_gshhs(*data, write_to);
    if (!w) {
      std::fprintf(stderr, "%s\n", w.error().to_string().c_str());
      return 1;
    }
    timer.row("write GSHHS");
  }
  if (args[1] == "-") {
    std::printf("%s: %zu points in %zu rings, read in %.3f s (wall), peak %.0f MB\n", file.c_str(), points,
                data->rings.size(), rows[0].wall, rows[0].peak);
    return 0;
  }
  ImportOptions o;
  o.gamma = [gamma](std::span<const Vec3>, std::span<double> g) {
    for (double& x : g) x = gamma;
  };
  // As examples/world_ocean.geo sets its Coastline (CloseStraits 1, MinChannelWidth
  // CoastAccuracy, KeepPassages 1; AntarcticaLevel 5 and DeviationFactor 0.5 are the
  // import's defaults) with the scale runs' CoastMinArea 0 (docs/benchmarks_scale.md).
  o.repair.close_straits = true;
  o.passages.min_width = gamma;
  o.passages.keep_passages = true;
  o.coarsen.min_area_km2 = 0;
  o.threads = threads;
  o.progress = &timer;
  auto m = build_coast_model(std::move(*data), o);
  if (!m) {
    std::fprintf(stderr, "%s\n", m.error().to_string().c_str());
    return 1;
  }
  std::size_t control = 0;
  std::uint64_t hash = 1469598103934665603ull;   // FNV-1a of every control point's bytes
  for (const CoastCurve& c : m->curves) {
    control += c.ll.size();
    const auto* b = reinterpret_cast<const unsigned char*>(c.ll.data());
    for (std::size_t i = 0; i < c.ll.size() * sizeof(geo::LonLat); ++i) hash = (hash ^ b[i]) * 1099511628211ull;
  }
  std::printf("%s: %zu points in, gamma %.0f m, %d thread(s): %zu loops, %zu control points, %zu repair rounds\n",
              file.c_str(), points, gamma, threads, m->loops.size(), control, m->report.repair_rounds);
  std::printf("points as lon/lat doubles: %.0f MB; model hash %016llx (the same for every thread count)\n",
              static_cast<double>(points) * 16.0 / 1048576.0, static_cast<unsigned long long>(hash));
  std::printf("%-12s %8s %8s %9s\n", "step", "wall_s", "cpu_s", "peak_MB");
  double wall = 0, cpu = 0;
  // The "repair" step (progress unit 6) runs from the deviation pass to the passages; the
  // import's account (ImportReport::step_cpu) names its parts, shown indented under it
  // (their peak is the step's).
  static const char* const parts[] = {"deviation", "repair", "straits", "orient", "passages"};
  for (const Row& r : rows) {
    std::printf("%-12s %8.3f %8.3f %9.0f\n", r.name.c_str(), r.wall, r.cpu, r.peak);
    wall += r.wall;
    cpu += r.cpu;
    if (r.name != "repair") continue;
    for (const char* part : parts)
      for (const ImportStepTime& t : m->report.step_cpu)
        if (t.name == part) std::printf("  %-10s %8.3f %8.3f %9s\n", part, t.wall, t.seconds, "-");
  }
  std::printf("%-12s %8.3f %8.3f %9.0f\n", "total", wall, cpu, peak_mb());
  return 0;
}
