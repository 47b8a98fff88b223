// del2d and front2d on the unit square with uniform size h (default 0.002,
// ~660k and ~580k triangles), side by side with Gmsh 4.8.4's `-2 -algo del2d`
// and `-2 -algo front2d` on the same geometry when gmsh is installed; and
// meshadapt (Gmsh's column only for h >= 0.005: it takes ~250 s at 0.002).
// With --threads N (or --thread-table: 1, 2, 4, 8, 16) del2d and front2d also run
// refine_partitioned (mesh/partition.h) on N threads: time, speed-up over 1 thread, peak
// memory per triangle, quality, and a hash showing the mesh is the same for every N.
// Usage: bench_mesh_square [h] [--no-gmsh] [--algo del2d|front2d|meshadapt|all]
//                          [--threads N[,N...] | --thread-table] [--no-whole]
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../unit/mesh/testing_domains.h"
#include "mesh/frontal.h"
#include "mesh/meshadapt.h"
#include "mesh/partition.h"
#include "mesh/modify/smooth.h"
#include "mesh/quality.h"
#include "mesh/refine.h"

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double process_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Resident memory of the process in bytes: "VmRSS" now or "VmHWM" (the peak since the
// last reset_peak_memory()); 0 when /proc is not there.
double memory_bytes(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) return 1024.0 * std::atof(line.c_str() + key.size());
  return 0;
}

// Linux: writing 5 to clear_refs resets VmHWM to the current resident size.
void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

// FNV-1a over the vertex coordinates and the triangles: equal meshes, equal hashes.
std::uint64_t mesh_hash(const sm::TriangleStore& m) {
  std::uint64_t h = 1469598103934665603ull;
  auto eat = [&h](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  eat(m.xy.data(), m.xy.size() * sizeof(sm::Vec2));
  eat(m.corner.data(), m.corner.size() * sizeof(sm::VertexId));
  return h;
}

// Meshes the square with one algorithm, smooths once (Gmsh's default
// Mesh.Smoothing = 1) and prints the figures. False on failure.
bool run_ours(double h, bool frontal) {
  const char* name = frontal ? "front2d" : "del2d";
  reset_peak_memory();
  const double rss0 = memory_bytes("VmRSS");
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  sm::TriangleStore m;
  const sm::Loop sq = sm::testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  if (!sm::testing::boundary_mesh(m, {sq})) return std::fprintf(stderr, "boundary mesh failed\n"), false;
  const double t_boundary = since(t0);
  sm::RefineOptions opt;
  opt.size = h;
  sm::RefineResult r;
  sm::FrontalResult fr;
  if (frontal) fr = sm::refine_front2d(m, opt), r = fr;
  else r = sm::refine_del2d(m, opt);
  const double t_refined = since(t0), c_refined = cpu_seconds() - c0;
  if (!r.ok()) return std::fprintf(stderr, "%s: %s\n", name, r.error.c_str()), false;
  const auto q0 = sm::mesh_quality(m, [&](sm::Vec2) { return h; });  // not timed
  const auto t1 = std::chrono::steady_clock::now();
  const double c1 = cpu_seconds();
  sm::smooth_laplacian(m, 1);
  const double t_smooth = since(t1), c_smooth = cpu_seconds() - c1;
  const double t_total = t_refined + t_smooth, c_total = c_refined + c_smooth;
  const double peak = memory_bytes("VmHWM") - rss0;
  const auto q = sm::mesh_quality(m, [&](sm::Vec2) { return h; });
  std::printf("stereomesh %s, unit square, h = %g\n", name, h);
  std::printf("  peak memory %.1f MB above the start, %.1f bytes per triangle\n", peak / 1e6, peak / q.triangles);
  std::printf(
      "  %u nodes, %u triangles; boundary %.3f s, refine %.3f s, smoothing %.3f s; total %.3f s wall, %.3f s CPU\n",
      q.nodes, q.triangles, t_boundary, t_refined - t_boundary, t_smooth, t_total, c_total);
  std::printf("  CPU: boundary + refine %.3f s (%.0f triangles/s), smoothing %.3f s\n", c_refined,
              q.triangles / c_refined, c_smooth);
  std::printf("  before smoothing: rho > 0.9: %.2f%%, min rho %.3f, mean %.3f\n", 100 * q0.share_rho_09, q0.min_rho,
              q0.mean_rho);
  std::printf("  %.0f triangles/s (wall), %.0f triangles/s (CPU)\n", q.triangles / t_total, q.triangles / c_total);
  std::printf(
      "  rho: min %.3f mean %.3f, share > 0.9: %.2f%%; edge/h median %.3f, 5-95%% [%.3f, %.3f], in [0.7,1.4] %.2f%%\n",
      q.min_rho, q.mean_rho, 100 * q.share_rho_09, q.len_median, q.len_p05, q.len_p95, 100 * q.share_len_07_14);
  std::printf("  %llu insertions, %llu rejected, %llu heap pops (%llu stale), %.2f walk steps/insertion\n",
              static_cast<unsigned long long>(r.stats.inserted), static_cast<unsigned long long>(r.stats.rejected),
              static_cast<unsigned long long>(r.stats.pops), static_cast<unsigned long long>(r.stats.stale),
              double(r.stats.walk_steps) / double(r.stats.inserted ? r.stats.inserted : 1));
  if (frontal)
    std::printf("  %llu frontal points, %llu circumcentre fallbacks, %llu given up\n",
                static_cast<unsigned long long>(fr.frontal_points),
                static_cast<unsigned long long>(fr.circumcentre_fallbacks),
                static_cast<unsigned long long>(fr.given_up));
  return true;
}

// The square refined in parts (refine_partitioned, default PartitionOptions) on each
// thread count, then one smoothing pass: wall time, speed-up over the first count, peak
// memory, quality, hash. False on failure or when two thread counts differ.
bool run_threads(double h, bool frontal, const std::vector<int>& counts, bool whole_first) {
  const char* name = frontal ? "front2d" : "del2d";
  std::printf("stereomesh %s in parts, unit square, h = %g, %u hardware threads\n", name, h,
              std::thread::hardware_concurrency());
  std::printf("  threads | parts | triangles | coarse s | parts s | merge s | smooth s | total wall s | process CPU s "
              "| speed-up | bytes/tri | rho>0.9 | in [0.7,1.4] | hash\n");
  if (whole_first) {
    // The same refinement in one piece: the reference for quality and time.
    reset_peak_memory();
    const double rss0 = memory_bytes("VmRSS");
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    sm::TriangleStore m;
    const sm::Loop sq = sm::testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
    if (!sm::testing::boundary_mesh(m, {sq})) return std::fprintf(stderr, "boundary mesh failed\n"), false;
    sm::RefineOptions ro;
    if (!frontal) ro.radius_limit = 0.73;
    ro.size = h;
    const sm::RefineResult r = frontal ? sm::RefineResult(sm::refine_front2d(m, ro)) : sm::refine_del2d(m, ro);
    if (!r.ok()) return std::fprintf(stderr, "%s: %s\n", name, r.error.c_str()), false;
    const auto t1 = std::chrono::steady_clock::now();
    sm::smooth_laplacian(m, 1);
    const double t_smooth = since(t1), t_total = since(t0), c_total = process_cpu_seconds() - c0;
    const double peak = memory_bytes("VmHWM") - rss0;
    const auto q = sm::mesh_quality(m, [&](sm::Vec2) { return h; });
    std::printf(
        "    whole |     1 | %9u |          |         |         | %8.3f | %12.3f | %13.3f |          | %9.1f | %6.2f%% "
        "| %11.2f%% | (min rho %.3f)\n",
        q.triangles, t_smooth, t_total, c_total, peak / q.triangles, 100 * q.share_rho_09, 100 * q.share_len_07_14,
        q.min_rho);
  }
  double first = 0;
  std::uint64_t first_hash = 0;
  bool same = true;
  for (int threads : counts) {
    reset_peak_memory();
    const double rss0 = memory_bytes("VmRSS");
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    sm::TriangleStore m;
    const sm::Loop sq = sm::testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
    if (!sm::testing::boundary_mesh(m, {sq})) return std::fprintf(stderr, "boundary mesh failed\n"), false;
    sm::RefineOptions ro;
    if (!frontal) ro.radius_limit = 0.73;   // mesh2d's del2d bound
    const auto make = [h]() -> sm::PlaneSizeFn {
      return [h](std::span<const sm::Vec2>, std::span<double> out) { std::fill(out.begin(), out.end(), h); };
    };
    const sm::PartitionResult r = sm::refine_partitioned(
        m, ro, frontal ? sm::PartRefiner::Frontal : sm::PartRefiner::Del2d, make, sm::PartitionOptions{}, threads);
    if (!r.ok()) return std::fprintf(stderr, "%s in parts: %s\n", name, r.error.c_str()), false;
    const auto t1 = std::chrono::steady_clock::now();
    sm::smooth_laplacian(m, 1, threads);
    const double t_smooth = since(t1), t_total = since(t0), c_total = process_cpu_seconds() - c0;
    const double peak = memory_bytes("VmHWM") - rss0;
    const std::uint64_t hash = mesh_hash(m);
    if (first == 0) first = t_total, first_hash = hash;
    same = same && hash == first_hash;
    const auto q = sm::mesh_quality(m, [&](sm::Vec2) { return h; });
    std::printf(
        "  %7d | %5u | %9u | %8.3f | %7.3f | %7.3f | %8.3f | %12.3f | %13.3f | %7.2fx | %9.1f | %6.2f%% | %11.2f%% | "
        "%016llx (min rho %.3f)\n",
        threads, r.stats.parts, q.triangles, r.stats.seconds_coarse, r.stats.seconds_parts, r.stats.seconds_merge,
        t_smooth, t_total, c_total, first / t_total, peak / q.triangles, 100 * q.share_rho_09, 100 * q.share_len_07_14,
        static_cast<unsigned long long>(hash), q.min_rho);
    std::fflush(stdout);
  }
  std::printf("  the same mesh for every thread count: %s\n", same ? "yes" : "NO");
  return same;
}

// meshadapt from the boundary mesh (its own smoothing included), then the
// same figures. False on failure.
bool run_meshadapt(double h) {
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  sm::TriangleStore m;
  const sm::Loop sq = sm::testing::polygon_loop(m, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h, false);
  if (!sm::testing::boundary_mesh(m, {sq})) return std::fprintf(stderr, "boundary mesh failed\n"), false;
  const double t_boundary = since(t0);
  sm::MeshAdaptOptions opt;
  opt.size = h;
  const auto r = sm::mesh_adapt(m, opt);
  const double t_total = since(t0), c_total = cpu_seconds() - c0;
  if (!r.ok()) return std::fprintf(stderr, "meshadapt: %s\n", r.error.c_str()), false;
  const auto q = sm::mesh_quality(m, [&](sm::Vec2) { return h; });
  std::printf("stereomesh meshadapt, unit square, h = %g\n", h);
  std::printf(
      "  %u nodes, %u triangles; boundary %.3f s, adapt %.3f s; total %.3f s wall, %.3f s CPU (%.0f triangles/s)\n",
      q.nodes, q.triangles, t_boundary, t_total - t_boundary, t_total, c_total, q.triangles / c_total);
  std::printf(
      "  rho: min %.3f mean %.3f, share > 0.9: %.2f%%; edge/h median %.3f, 5-95%% [%.3f, %.3f], in [0.7,1.4] %.2f%%\n",
      q.min_rho, q.mean_rho, 100 * q.share_rho_09, q.len_median, q.len_p05, q.len_p95, 100 * q.share_len_07_14);
  std::printf("  %u rounds, %llu splits, %llu collapses (%llu refused), %llu swaps, %llu smoothing moves\n",
              r.stats.iterations, static_cast<unsigned long long>(r.stats.splits),
              static_cast<unsigned long long>(r.stats.collapses),
              static_cast<unsigned long long>(r.stats.collapses_refused),
              static_cast<unsigned long long>(r.stats.swaps), static_cast<unsigned long long>(r.stats.smoothed));
  return true;
}

// The triangles of a Gmsh MSH 4.1 ASCII file measured like ours (rho, edge
// length over h), printed on one line; nothing when the file cannot be read.
void print_msh_quality(const std::string& path, double h) {
  std::ifstream in(path);
  std::string line;
  std::vector<sm::Vec2> xy;
  std::vector<std::size_t> tag_of;  // node tag -> index
  std::vector<std::array<std::uint32_t, 3>> tris;
  while (std::getline(in, line)) {
    if (line == "$Nodes") {
      std::size_t blocks = 0, n = 0, lo = 0, hi = 0;
      in >> blocks >> n >> lo >> hi;
      tag_of.assign(hi + 1, 0);
      for (std::size_t b = 0; b < blocks; ++b) {
        int dim = 0, ent = 0, param = 0;
        std::size_t k = 0;
        in >> dim >> ent >> param >> k;
        std::vector<std::size_t> tags(k);
        for (auto& t : tags) in >> t;
        for (std::size_t i = 0; i < k; ++i) {
          double x = 0, y = 0, z = 0, u = 0;
          in >> x >> y >> z;
          for (int p = 0; p < param * dim; ++p) in >> u;
          tag_of[tags[i]] = xy.size();
          xy.push_back({x, y});
        }
      }
    } else if (line == "$Elements") {
      std::size_t blocks = 0, n = 0, lo = 0, hi = 0;
      in >> blocks >> n >> lo >> hi;
      for (std::size_t b = 0; b < blocks; ++b) {
        int dim = 0, ent = 0, type = 0;
        std::size_t k = 0;
        in >> dim >> ent >> type >> k;
        const int nn = type == 15 ? 1 : type == 1 ? 2 : type == 2 ? 3 : 0;
        for (std::size_t i = 0; i < k; ++i) {
          std::size_t tag = 0, v[3] = {0, 0, 0};
          in >> tag;
          for (int j = 0; j < nn; ++j) in >> v[j];
          if (type == 2)
            tris.push_back({static_cast<std::uint32_t>(tag_of[v[0]]), static_cast<std::uint32_t>(tag_of[v[1]]),
                            static_cast<std::uint32_t>(tag_of[v[2]])});
        }
      }
    }
  }
  if (tris.empty()) return;
  if (sm::orient2d(xy[tris[0][0]], xy[tris[0][1]], xy[tris[0][2]]) == sm::Sign::Negative)
    for (auto& t : tris) std::swap(t[1], t[2]);
  sm::TriangleStore m;
  if (!sm::build_triangulation(xy, tris, m)) return;
  const auto q = sm::mesh_quality(m, [&](sm::Vec2) { return h; });
  std::printf("  measured like ours: %u triangles; rho: min %.3f mean %.3f, share > 0.9: %.2f%%; edge/h median %.3f, "
              "5-95%% [%.3f, %.3f], in [0.7,1.4] %.2f%%\n",
              q.triangles, q.min_rho, q.mean_rho, 100 * q.share_rho_09, q.len_median, q.len_p05, q.len_p95,
              100 * q.share_len_07_14);
}

void run_gmsh(double h, const char* algo) {
  // One directory per run: several benchmarks may run Gmsh at once.
  const std::string dir = "/tmp/stereomesh_bench_square_" + std::to_string(getpid());
  std::system(("mkdir -p " + dir).c_str());
  std::ofstream(dir + "/sq.geo") << "lc = " << h << ";\n"
                                 << "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc};\n"
                                 << "Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};\n"
                                 << "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                                 << "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n";
  std::fflush(stdout);  // our lines before the ones the shell prints
  const auto g0 = std::chrono::steady_clock::now();
  const std::string log = dir + "/gmsh_" + algo + ".log";
  const int rc = std::system(("cd " + dir + " && gmsh sq.geo -2 -algo " + algo + " -nt 1 -o sq_" + algo +
                              ".msh > " + log + " 2>&1").c_str());
  const double tg = since(g0);
  std::printf("gmsh 4.8.4 -2 -algo %s: %.3f s wall (exit %d); its summary:\n", algo, tg, rc);
  std::fflush(stdout);
  std::system(("grep -E 'Done meshing 2D|nodes .* elements' " + log + " | sed 's/^/  /'").c_str());
  if (rc == 0) print_msh_quality(dir + "/sq_" + algo + ".msh", h);
  std::system(("rm -rf " + dir).c_str());
}

// "1,2,4": thread counts, each at least 1.
std::vector<int> parse_counts(const char* text) {
  std::vector<int> out;
  for (const char* c = text; *c;) {
    out.push_back(std::max(1, std::atoi(c)));
    const char* comma = std::strchr(c, ',');
    c = comma ? comma + 1 : c + std::strlen(c);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  double h = 0.002;
  bool gmsh = true, del2d = true, front2d = true, meshadapt = true;
  std::vector<int> thread_counts;
  bool whole_first = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-gmsh") == 0) {
      gmsh = false;
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      thread_counts = parse_counts(argv[++i]);
    } else if (std::strcmp(argv[i], "--no-whole") == 0) {
      whole_first = false;   // the first row's peak memory then owes nothing to an earlier run
    } else if (std::strcmp(argv[i], "--thread-table") == 0) {
      thread_counts = {1, 2, 4, 8, 16};
    } else if (std::strcmp(argv[i], "--algo") == 0 && i + 1 < argc) {
      const std::string a = argv[++i];
      del2d = a == "del2d" || a == "all";
      front2d = a == "front2d" || a == "all";
      meshadapt = a == "meshadapt" || a == "all";
      if (!del2d && !front2d && !meshadapt)
        return std::fprintf(stderr, "--algo: del2d, front2d, meshadapt or all\n"), 2;
    } else {
      h = std::atof(argv[i]);
    }
  }
  if (!(h > 0))
    return std::fprintf(stderr, "usage: bench_mesh_square [h] [--no-gmsh] [--algo del2d|front2d|meshadapt|all] "
                                "[--threads N[,N...] | --thread-table] [--no-whole]\n"),
           2;
  // --no-whole: the runs in parts only (their peak memory measured first in the process).
  if (del2d && whole_first && !run_ours(h, false)) return 1;
  if (del2d && !thread_counts.empty() && !run_threads(h, false, thread_counts, whole_first)) return 1;
  if (front2d && whole_first && !run_ours(h, true)) return 1;
  if (front2d && !thread_counts.empty() && !run_threads(h, true, thread_counts, whole_first)) return 1;
  if (meshadapt && !run_meshadapt(h)) return 1;
  if (!gmsh) return 0;
  if (std::system("command -v gmsh >/dev/null 2>&1") != 0) {
    std::printf("gmsh: not installed, column skipped\n");
    return 0;
  }
  if (del2d) run_gmsh(h, "del2d");
  if (front2d) run_gmsh(h, "front2d");
  if (meshadapt && h >= 0.005) run_gmsh(h, "meshadapt");
  else if (meshadapt) std::printf("gmsh -algo meshadapt: skipped below h = 0.005 (about 250 s at 0.002)\n");
  return 0;
}
