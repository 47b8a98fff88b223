// meshadapt and del2d on a spherical cap (unit sphere, angular radius 60
// degrees round the North Pole, uniform size delta on the sphere, default
// 0.01: ~72k triangles) meshed in the stereographic plane of a PolarSphere,
// side by side with Gmsh 4.8.4 on the same script (a 180-gon of Lines in
// (u, v), MathEval size) when gmsh is installed. Quality and lengths are
// measured on the sphere for both. Usage: bench_mesh_cap [delta] [--no-gmsh]
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "../unit/mesh/testing_domains.h"
#include "mesh/meshadapt.h"
#include "mesh/modify/smooth.h"
#include "mesh/refine.h"

namespace {

constexpr int kSides = 180;

double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

sm::Vec3 on_sphere(sm::Vec2 u) {
  const double r2 = sm::norm2(u);
  return {2 * u.x / (1 + r2), 2 * u.y / (1 + r2), (1 - r2) / (1 + r2)};
}

// rho of the flat triangles through the points on the sphere and great-circle
// edge lengths over delta, for triangles given as 3D points.
void print_sphere_quality(const std::vector<sm::Vec3>& p, const std::vector<std::array<std::uint32_t, 3>>& tris,
                          double delta) {
  std::size_t good = 0, in = 0, edges = 0;
  double min_rho = 1, sum_rho = 0;
  std::vector<double> len;
  for (const auto& t : tris) {
    const sm::Vec3 a = p[t[0]], b = p[t[1]], c = p[t[2]];
    const double la = sm::norm(b - c), lb = sm::norm(c - a), lc = sm::norm(a - b);
    const double area = 0.5 * sm::norm(sm::cross(b - a, c - a));
    const double r = 16 * area * area / ((la + lb + lc) * la * lb * lc);
    good += r > 0.9, sum_rho += r, min_rho = std::min(min_rho, r);
    for (int e = 0; e < 3; ++e) {  // each interior edge twice, boundary once: fine for shares
      const sm::Vec3 u = p[t[e]], v = p[t[(e + 1) % 3]];
      const double arc = std::atan2(sm::norm(sm::cross(u, v)), sm::dot(u, v)) / delta;
      in += arc >= 0.7 && arc <= 1.4, ++edges;
      len.push_back(arc);
    }
  }
  std::sort(len.begin(), len.end());
  std::printf("  on the sphere: %zu triangles; rho: min %.3f mean %.3f, share > 0.9: %.2f%%; arc/delta median %.3f, "
              "5-95%% [%.3f, %.3f], in [0.7,1.4] %.2f%%\n",
              tris.size(), min_rho, sum_rho / tris.size(), 100.0 * good / tris.size(), len[len.size() / 2],
              len[len.size() / 20], len[len.size() * 19 / 20], 100.0 * in / edges);
}

bool run_ours(double delta, bool adapt) {
  const double c0 = cpu_seconds();
  sm::TriangleStore m;
  // The 180-gon of the script, each side cut into pieces of about delta on the sphere.
  const double r = std::tan(M_PI / 6);
  sm::Loop loop;
  for (int i = 0; i < kSides; ++i) {
    const sm::Vec2 a{r * std::cos(2 * M_PI * i / kSides), r * std::sin(2 * M_PI * i / kSides)};
    const sm::Vec2 b{r * std::cos(2 * M_PI * (i + 1) / kSides), r * std::sin(2 * M_PI * (i + 1) / kSides)};
    const sm::Vec3 pa = on_sphere(a), pb = on_sphere(b);
    const int n = std::max(
        1, static_cast<int>(std::ceil(std::atan2(sm::norm(sm::cross(pa, pb)), sm::dot(pa, pb)) / delta - 1e-9)));
    for (int k = 0; k < n; ++k) loop.v.push_back(m.add_vertex(a + (double(k) / n) * (b - a)));
  }
  if (!sm::testing::boundary_mesh(m, {loop})) return std::fprintf(stderr, "boundary mesh failed\n"), false;
  const auto size_at = [delta](std::span<const sm::Vec2> pts, std::span<double> h) {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = delta * (1 + sm::norm2(pts[i])) / 2;  // delta / lambda
  };
  std::string error;
  if (adapt) {
    sm::MeshAdaptOptions opt;
    opt.size_at = size_at;
    const auto res = sm::mesh_adapt(m, opt);
    error = res.error;
  } else {
    sm::RefineOptions opt;
    opt.size_at = size_at;
    const auto res = sm::refine_del2d(m, opt);
    error = res.error;
    sm::smooth_laplacian(m, 1);
  }
  const double cpu = cpu_seconds() - c0;
  if (!error.empty()) return std::fprintf(stderr, "%s\n", error.c_str()), false;
  std::vector<sm::Vec3> p;
  for (const sm::Vec2 u : m.xy) p.push_back(on_sphere(u));
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t t = 0; t < m.num_slots(); ++t)
    if (m.alive(sm::TriId{t}))
      tris.push_back(
          {m.vertex(sm::TriId{t}, 0).value, m.vertex(sm::TriId{t}, 1).value, m.vertex(sm::TriId{t}, 2).value});
  std::printf("stereomesh %s, cap of 60 degrees, delta = %g: %u nodes, %.3f s CPU (%.0f triangles/s)\n",
              adapt ? "meshadapt" : "del2d + 1 smoothing", delta, m.num_vertices(), cpu, tris.size() / cpu);
  print_sphere_quality(p, tris, delta);
  return true;
}

// Nodes (3D) and triangles of a Gmsh MSH 4.1 ASCII file.
bool read_msh(const std::string& path, std::vector<sm::Vec3>& p, std::vector<std::array<std::uint32_t, 3>>& tris) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::uint32_t> index;
  while (std::getline(in, line)) {
    if (line == "$Nodes") {
      std::size_t blocks = 0, n = 0, lo = 0, hi = 0;
      in >> blocks >> n >> lo >> hi;
      index.assign(hi + 1, 0);
      for (std::size_t b = 0; b < blocks; ++b) {
        int dim = 0, ent = 0, param = 0;
        std::size_t k = 0;
        in >> dim >> ent >> param >> k;
        std::vector<std::size_t> tags(k);
        for (auto& t : tags) in >> t;
        for (std::size_t i = 0; i < k; ++i) {
          sm::Vec3 x{};
          double u = 0;
          in >> x.x >> x.y >> x.z;
          for (int j = 0; j < param * dim; ++j) in >> u;
          index[tags[i]] = static_cast<std::uint32_t>(p.size());
          p.push_back(x);
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
          if (type == 2) tris.push_back({index[v[0]], index[v[1]], index[v[2]]});
        }
      }
    }
  }
  return !tris.empty();
}

void run_gmsh(double delta, const char* algo) {
  const std::string dir = "/tmp/stereomesh_bench_cap";
  std::system(("mkdir -p " + dir).c_str());
  std::ofstream(dir + "/cap.geo")
      << "Point(1) = {0, 0, 0};\nPoint(2) = {0, 0, 1};\nPolarSphere(1) = {1, 2};\n"
      << "r = Tan(Pi / 6);\nn = " << kSides << ";\n"
      << "For i In {0:n - 1}\n"
      << "  Point(10 + i) = {r * Cos(2 * Pi * i / n), r * Sin(2 * Pi * i / n), 0};\n"
      << "EndFor\nFor i In {0:n - 1}\n  Line(10 + i) = {10 + i, 10 + (i + 1) % n};\nEndFor\n"
      << "Curve Loop(1) = {10 : 10 + n - 1};\nPlane Surface(1) = {1};\n"
      << "Field[1] = MathEval;\nField[1].F = \"" << delta << "\";\nBackground Field = 1;\n"
      << "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeExtendFromBoundary = 0;\n";
  std::fflush(stdout);
  const std::string log = dir + "/gmsh_" + algo + ".log", msh = dir + "/cap_" + algo + ".msh";
  const int rc = std::system(("cd " + dir + " && gmsh cap.geo -2 -algo " + algo + " -nt 1 -o " + msh + " > " + log +
                              " 2>&1").c_str());
  std::printf("gmsh 4.8.4 -2 -algo %s (exit %d); its summary:\n", algo, rc);
  std::fflush(stdout);
  std::system(("grep -E 'Done meshing 2D|nodes .* elements' " + log + " | sed 's/^/  /'").c_str());
  std::vector<sm::Vec3> p;
  std::vector<std::array<std::uint32_t, 3>> tris;
  if (read_msh(msh, p, tris)) print_sphere_quality(p, tris, delta);
}

}  // namespace

int main(int argc, char** argv) {
  double delta = 0.01;
  bool gmsh = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-gmsh") == 0) gmsh = false;
    else delta = std::atof(argv[i]);
  }
  if (!(delta > 0)) return std::fprintf(stderr, "usage: bench_mesh_cap [delta] [--no-gmsh]\n"), 2;
  if (!run_ours(delta, true) || !run_ours(delta, false)) return 1;
  if (!gmsh) return 0;
  if (std::system("command -v gmsh >/dev/null 2>&1") != 0) {
    std::printf("gmsh: not installed, column skipped\n");
    return 0;
  }
  run_gmsh(delta, "meshadapt");
  run_gmsh(delta, "del2d");
  return 0;
}
