// del2d and front2d on the unit square with uniform size h (default 0.002,
// ~660k and ~580k triangles), side by side with Gmsh 4.8.4's `-2 -algo del2d`
// and `-2 -algo front2d` on the same geometry when gmsh is installed; and
// meshadapt (Gmsh's column only for h >= 0.005: it takes ~250 s at 0.002).
// Usage: bench_mesh_square [h] [--no-gmsh] [--algo del2d|front2d|meshadapt|all]
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "../unit/mesh/testing_domains.h"
#include "mesh/frontal.h"
#include "mesh/meshadapt.h"
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

// Meshes the square with one algorithm, smooths once (Gmsh's default
// Mesh.Smoothing = 1) and prints the figures. False on failure.
bool run_ours(double h, bool frontal) {
  const char* name = frontal ? "front2d" : "del2d";
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
  const auto q = sm::mesh_quality(m, [&](sm::Vec2) { return h; });
  std::printf("stereomesh %s, unit square, h = %g\n", name, h);
  std::printf("  %u nodes, %u triangles; boundary %.3f s, refine %.3f s, smoothing %.3f s; total %.3f s wall, %.3f s CPU\n",
              q.nodes, q.triangles, t_boundary, t_refined - t_boundary, t_smooth, t_total, c_total);
  std::printf("  CPU: boundary + refine %.3f s (%.0f triangles/s), smoothing %.3f s\n", c_refined, q.triangles / c_refined,
              c_smooth);
  std::printf("  before smoothing: rho > 0.9: %.2f%%, min rho %.3f, mean %.3f\n", 100 * q0.share_rho_09, q0.min_rho,
              q0.mean_rho);
  std::printf("  %.0f triangles/s (wall), %.0f triangles/s (CPU)\n", q.triangles / t_total, q.triangles / c_total);
  std::printf("  rho: min %.3f mean %.3f, share > 0.9: %.2f%%; edge/h median %.3f, 5-95%% [%.3f, %.3f], in [0.7,1.4] %.2f%%\n",
              q.min_rho, q.mean_rho, 100 * q.share_rho_09, q.len_median, q.len_p05, q.len_p95,
              100 * q.share_len_07_14);
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
  std::printf("  %u nodes, %u triangles; boundary %.3f s, adapt %.3f s; total %.3f s wall, %.3f s CPU (%.0f triangles/s)\n",
              q.nodes, q.triangles, t_boundary, t_total - t_boundary, t_total, c_total, q.triangles / c_total);
  std::printf("  rho: min %.3f mean %.3f, share > 0.9: %.2f%%; edge/h median %.3f, 5-95%% [%.3f, %.3f], in [0.7,1.4] %.2f%%\n",
              q.min_rho, q.mean_rho, 100 * q.share_rho_09, q.len_median, q.len_p05, q.len_p95,
              100 * q.share_len_07_14);
  std::printf("  %u rounds, %llu splits, %llu collapses (%llu refused), %llu swaps, %llu smoothing moves\n",
              r.stats.iterations, static_cast<unsigned long long>(r.stats.splits),
              static_cast<unsigned long long>(r.stats.collapses), static_cast<unsigned long long>(r.stats.collapses_refused),
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

}  // namespace

int main(int argc, char** argv) {
  double h = 0.002;
  bool gmsh = true, del2d = true, front2d = true, meshadapt = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-gmsh") == 0) {
      gmsh = false;
    } else if (std::strcmp(argv[i], "--algo") == 0 && i + 1 < argc) {
      const std::string a = argv[++i];
      del2d = a == "del2d" || a == "all";
      front2d = a == "front2d" || a == "all";
      meshadapt = a == "meshadapt" || a == "all";
      if (!del2d && !front2d && !meshadapt) return std::fprintf(stderr, "--algo: del2d, front2d, meshadapt or all\n"), 2;
    } else {
      h = std::atof(argv[i]);
    }
  }
  if (!(h > 0)) return std::fprintf(stderr, "usage: bench_mesh_square [h] [--no-gmsh] [--algo del2d|front2d|meshadapt|all]\n"), 2;
  if (del2d && !run_ours(h, false)) return 1;
  if (front2d && !run_ours(h, true)) return 1;
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
