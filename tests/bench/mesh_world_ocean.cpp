// The world ocean on an Earth-radius PolarSphere: GSHHG shorelines through the
// coast import, closed BSplines, shore-distance size 30 to 200 km within 500 km (Distance +
// linear Threshold), 1D + 2D meshing per algorithm with time per stage and quality; then
// the same model through `gmsh -2` (the .geo from the coast module's Plugin(GSHHS) writer).
// Usage: bench_mesh_world_ocean [file=world_l.txt] [gamma_km=30] [algorithms=5,6] [gmsh=1] [out.msh]
//                               [--size-scale S] [--threads N[,N...] | --thread-table] [--part-triangles N]
// (out.msh: our mesh of the last algorithm through io::from_model_mesh, MSH 4.1;
// --size-scale divides the 30-200 km sizes by S, e.g. 4 for a face of ~1.3M triangles;
// --threads / --thread-table (1, 2, 4, 8, 16) mesh 2D again in parts (mesh/partition.h) on
// N threads: wall time, speed-up, quality against the face meshed in one piece, same mesh;
// --part-triangles N: parts of about N triangles, faces from 2N up refined in parts, so the
// 80k-triangle face of the default sizes can be cut; finer sizes (--size-scale 2, 4, 8:
// 0.3M to 5M triangles) mesh too since the coast import's B-spline crossing check is on).
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "coast/gshhs_plugin_geo.h"
#include "coast/import.h"
#include "coast/read.h"
#include "field/distance.h"
#include "io/from_model_mesh.h"
#include "io/msh_writer.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"
#include "mesh/mesh_stats.h"

namespace {

constexpr double kLcMin = 30e3, kLcMax = 200e3, kDistMin = 0, kDistMax = 500e3;

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Gmsh's Threshold, linear, StopAtDistMax off (docs/fields.md).
class Threshold : public sm::field::SizeField {
 public:
  Threshold(sm::field::FieldPtr d, double scale) : d_(std::move(d)), scale_(scale) {}
  void eval(std::span<const sm::Vec3> pts, std::span<double> h) const override {
    d_->eval(pts, h);
    for (double& x : h) {
      const double r = std::clamp((x - kDistMin) / (kDistMax - kDistMin), 0.0, 1.0);
      x = (kLcMin * (1 - r) + kLcMax * r) / scale_;
    }
  }

 private:
  sm::field::FieldPtr d_;
  double scale_;
};

// The coast model as geometry, as the Plugin(GSHHS) .geo describes it: a PolarSphere of
// the plugin's radius, points at the curves' (u,v), one closed BSpline per island, BSplines
// (or Lines for two points) for pieces, loops and Plane Surfaces in model order.
sm::geo::Model build_model(const sm::coast::CoastModel& cm, double radius, std::vector<sm::Vec3>& coast_points) {
  sm::geo::Model m;
  auto must = [](const sm::geo::GeoStatus& s, const char* what) {
    if (!s.ok()) {
      std::fprintf(stderr, "model: %s failed\n", what);
      std::exit(1);
    }
  };
  must(m.add_point(1, {0, 0, 0}), "centre");
  must(m.add_point(2, {0, 0, radius}), "pole");
  must(m.add_polar_sphere(1, 1, 2), "PolarSphere");
  const sm::geo::PolarSphere ps = *m.geometry(1)->polar();
  std::vector<int> curve_tag(cm.curves.size(), 0);
  for (std::size_t l = 0; l < cm.loops.size(); ++l) {
    const sm::coast::CoastLoop& loop = cm.loops[l];
    std::vector<int> start(loop.curves.size());
    const int loop_first = m.new_point_tag();
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const sm::coast::CoastCurve& c = cm.curves[loop.curves[k]];
      start[k] = m.new_point_tag();
      const std::size_t n = c.periodic ? c.uv.size() : c.uv.size() - 1;
      for (std::size_t i = 0; i < n; ++i) {
        must(m.add_point(m.new_point_tag(), {c.uv[i].x, c.uv[i].y, 0}), "point");
        coast_points.push_back(ps.point(c.uv[i]));
      }
    }
    const int after = m.new_point_tag();
    std::vector<int> ids_loop;
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const sm::coast::CoastCurve& c = cm.curves[loop.curves[k]];
      const int first = start[k];
      const int last = k + 1 < loop.curves.size() ? start[k + 1] - 1 : after - 1;
      const int end = c.periodic ? first : (k + 1 < loop.curves.size() ? start[k + 1] : loop_first);
      std::vector<int> ids;
      for (int p = first; p <= last; ++p) ids.push_back(p);
      ids.push_back(end);
      const int tag = m.new_curve_tag();
      const auto kind = ids.size() == 2 ? sm::geo::CurveKind::Line : sm::geo::CurveKind::BSpline;
      must(m.add_curve(tag, kind, ids), "curve");
      curve_tag[loop.curves[k]] = tag;
      ids_loop.push_back(tag);
    }
    must(m.add_curve_loop(static_cast<int>(l) + 1, ids_loop), "curve loop");
  }
  for (std::size_t s = 0; s < cm.surfaces.size(); ++s) {
    std::vector<int> loops{static_cast<int>(cm.surfaces[s].outer) + 1};
    for (std::uint32_t h : cm.surfaces[s].holes) loops.push_back(static_cast<int>(h) + 1);
    must(m.add_plane_surface(static_cast<int>(s) + 1, loops), "plane surface");
  }
  return m;
}

// Process CPU seconds: the figure to compare on a shared machine (gmsh prints its own).
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

const char* algo_name(int a) { return a == 5 ? "del2d" : a == 6 ? "front2d" : a == 1 ? "meshadapt" : "auto"; }

// Nodes and triangles of an MSH 2.2 ASCII file as a ModelMesh (one surface).
bool read_msh22(const std::string& path, sm::ModelMesh& mesh) {
  std::ifstream in(path);
  std::string line;
  std::vector<long> id_to_node;
  while (std::getline(in, line)) {
    if (line == "$Nodes") {
      std::size_t n = 0;
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        long id;
        double x, y, z;
        in >> id >> x >> y >> z;
        if (id >= static_cast<long>(id_to_node.size())) id_to_node.resize(id + 1, -1);
        id_to_node[id] = static_cast<long>(mesh.add_node({x, y, z}));
      }
    } else if (line == "$Elements") {
      std::size_t n = 0;
      in >> n;
      std::getline(in, line);
      sm::SurfaceMesh& sf = mesh.surfaces[1];
      for (std::size_t i = 0; i < n; ++i) {
        std::getline(in, line);
        std::istringstream ls(line);
        long id, type, ntags;
        ls >> id >> type >> ntags;
        for (long t = 0; t < ntags; ++t) ls >> id;
        if (type != 2) continue;
        long a, b, c;
        ls >> a >> b >> c;
        sf.triangles.push_back({static_cast<std::uint32_t>(id_to_node[a]), static_cast<std::uint32_t>(id_to_node[b]),
                                static_cast<std::uint32_t>(id_to_node[c])});
      }
    }
  }
  return !mesh.nodes.empty();
}

// Seconds from gmsh's "Done meshing nD (Wall Xs, CPU Ys)" line.
double gmsh_stage(const std::string& log, const char* stage, bool cpu) {
  const std::size_t at = log.find(std::string("Done meshing ") + stage);
  if (at == std::string::npos) return -1;
  const std::size_t k = log.find(cpu ? "CPU " : "Wall ", at);
  return k == std::string::npos ? -1 : std::atof(log.c_str() + k + (cpu ? 4 : 5));
}

void print_stats(const char* who, const sm::MeshStats& st) {
  std::printf("  %-8s %9llu triangles, rho min %.2e mean %.4f, rho>0.9 %.2f%%, edge/size median %.3f [%.3f, %.3f] "
              "in [0.7,1.4] %.2f%%\n",
              who, static_cast<unsigned long long>(st.triangles), st.min_rho, st.mean_rho, 100 * st.share_rho_09,
              st.len_median, st.len_p05, st.len_p95, 100 * st.share_len_07_14);
}

}  // namespace

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

// The 2D mesh of one algorithm in one piece, then in parts on each thread count: wall
// time, speed-up over the first count, quality, and whether nodes and triangles are the
// same for every count.
void thread_table(const sm::geo::Model& model, const sm::Mesh1dResult& r1, sm::Mesh2dOptions o2,
                  const std::vector<int>& counts, const sm::SizeAt3& target) {
  std::printf("  2D in parts, %u hardware threads:\n", std::thread::hardware_concurrency());
  std::printf(
      "    threads | parts | estimate | triangles | 2D wall s | refine s | smooth s | speed-up | rho>0.9 | rho min | "
      "in [0.7,1.4]\n");
  std::vector<sm::MeshNode> first_nodes;
  std::map<int, sm::SurfaceMesh> first_faces;
  double first = 0;
  bool same = true;
  for (int run = -1; run < static_cast<int>(counts.size()); ++run) {
    const int threads = run < 0 ? 1 : counts[run];
    sm::Mesh2dOptions o = o2;
    o.threads = threads;
    if (run < 0) o.partition.min_triangles = 0;   // the whole face: the reference
    sm::ModelMesh mesh = r1.mesh;
    const auto t0 = std::chrono::steady_clock::now();
    const sm::Mesh2dResult r2 = sm::mesh_surfaces(model, mesh, o);
    const double wall = since(t0);
    if (!r2.ok()) {
      std::printf("    2D failed: problem %d on surface %d\n", static_cast<int>(r2.error.problem), r2.error.surface);
      return;
    }
    const sm::MeshStats st = sm::mesh_stats(mesh, target);
    if (run == 0) first = wall, first_nodes = mesh.nodes, first_faces = mesh.surfaces;
    if (run > 0) {
      bool eq = mesh.nodes.size() == first_nodes.size() && mesh.surfaces.size() == first_faces.size();
      for (std::size_t i = 0; eq && i < mesh.nodes.size(); ++i) eq = mesh.nodes[i].xyz == first_nodes[i].xyz;
      for (const auto& [tag, f] : mesh.surfaces) eq = eq && f.triangles == first_faces[tag].triangles;
      same = same && eq;
    }
    char label[16];
    std::snprintf(label, sizeof label, "%d", threads);
    std::printf("    %7s | %5llu | %8llu | %9llu | %9.3f | %8.3f | %8.3f | %7.2fx | %6.2f%% | %7.4f | %11.2f%%\n",
                run < 0 ? "whole" : label, static_cast<unsigned long long>(run < 0 ? 1 : r2.stats.parts),
                static_cast<unsigned long long>(r2.stats.estimated_triangles),
                static_cast<unsigned long long>(st.triangles), wall, r2.stats.seconds_refine, r2.stats.seconds_smooth,
                run < 0 || first == 0 ? 0.0 : first / wall, 100 * st.share_rho_09, st.min_rho,
                100 * st.share_len_07_14);
    std::fflush(stdout);
  }
  std::printf("    the same mesh for every thread count: %s\n", same ? "yes" : "NO");
}

int main(int argc, char** argv) {
  double size_scale = 1;
  std::vector<int> thread_counts;
  long part_triangles = 0;
  {
    // Flags out, positional arguments kept in order.
    int k = 1;
    for (int i = 1; i < argc; ++i) {
      if (std::strcmp(argv[i], "--size-scale") == 0 && i + 1 < argc) size_scale = std::atof(argv[++i]);
      else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) thread_counts = parse_counts(argv[++i]);
      else if (std::strcmp(argv[i], "--thread-table") == 0) thread_counts = {1, 2, 4, 8, 16};
      else if (std::strcmp(argv[i], "--part-triangles") == 0 && i + 1 < argc) part_triangles = std::atol(argv[++i]);
      else argv[k++] = argv[i];
    }
    argc = k;
    if (!(size_scale > 0)) return std::fprintf(stderr, "--size-scale must be positive\n"), 2;
  }
  const std::string file = argc > 1 ? argv[1] : "world_l.txt";
  const double gamma_km = argc > 2 ? std::atof(argv[2]) : 30.0;
  const std::string algos = argc > 3 ? argv[3] : "5,6";
  const bool with_gmsh = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  const std::string out_msh = argc > 5 ? argv[5] : "";
  const std::string path = std::string(SM_DATA_DIR) + "/gshhg/" + file;
  const double radius = sm::geo::kEarthRadius;

  auto t0 = std::chrono::steady_clock::now();
  auto coast = sm::coast::read_coastline(sm::coast::CoastFormat::LonLatText, path);
  if (!coast) return std::fprintf(stderr, "%s\n", coast.error().to_string().c_str()), 1;
  sm::coast::ImportOptions io;
  io.radius = radius;
  io.repair.check_splines = true;   // BSplines through the control points must not cross (1D would stop)
  io.gamma = [gamma_km](std::span<const sm::Vec3>, std::span<double> g) {
    std::fill(g.begin(), g.end(), gamma_km * 1e3);
  };
  auto cm = sm::coast::build_coast_model(std::move(*coast), io);
  if (!cm) return std::fprintf(stderr, "%s\n", cm.error().to_string().c_str()), 1;
  const double t_import = since(t0);
  t0 = std::chrono::steady_clock::now();
  std::vector<sm::Vec3> coast_points;
  const sm::geo::Model model = build_model(*cm, radius, coast_points);
  const double t_model = since(t0);
  std::printf("%s, gamma %g km: %zu curves, %zu loops, %zu surfaces, %zu coast points (import %.3f s, model %.3f s); "
              "splines that may cross: %zu\n",
              file.c_str(), gamma_km, cm->curves.size(), cm->loops.size(), cm->surfaces.size(), coast_points.size(),
              t_import, t_model, cm->report.count(sm::coast::RepairKind::SplineMayCross));
  const Threshold size(sm::field::make_distance_field(coast_points), size_scale);
  const auto target = [&](std::span<const sm::Vec3> pts, std::span<double> h) {
    std::vector<sm::Vec3> on(pts.begin(), pts.end());
    for (sm::Vec3& p : on) p = p * (radius / norm(p));
    size.eval(on, h);
  };
  sm::Mesh1dOptions o1;
  o1.background = &size;
  o1.size.from_points = false;
  o1.size.extend_from_boundary = 0;

  std::vector<int> list;
  for (std::size_t k = 0; k < algos.size();) {
    list.push_back(std::atoi(algos.c_str() + k));
    const std::size_t c = algos.find(',', k);
    k = c == std::string::npos ? algos.size() : c + 1;
  }
  std::map<int, double> ours_1d, ours_2d;   // CPU seconds per algorithm
  for (int a : list) {
    std::printf("Mesh.Algorithm = %d (%s), one thread\n", a, algo_name(a));
    t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    sm::Mesh1dResult r1 = sm::mesh_curves(model, o1);
    const double t1 = since(t0), c1 = cpu_seconds() - c0;
    if (!r1.ok())
      return std::fprintf(stderr, "1D: kind %d, problem %d\n", static_cast<int>(r1.error.kind),
                          static_cast<int>(r1.error.problem)),
             1;
    sm::Mesh2dOptions o2;
    o2.algorithm = static_cast<sm::Mesh2dAlgorithm>(a);
    o2.background = &size;
    o2.size = o1.size;
    t0 = std::chrono::steady_clock::now();
    const double c2start = cpu_seconds();
    const sm::Mesh2dResult r2 = sm::mesh_surfaces(model, r1.mesh, o2);
    const double t2 = since(t0), c2 = cpu_seconds() - c2start;
    if (!r2.ok())
      return std::fprintf(stderr, "2D: problem %d on surface %d\n", static_cast<int>(r2.error.problem),
                          r2.error.surface),
             1;
    sm::MeshStats st = sm::mesh_stats(r1.mesh, target);
    st.stages = {{"1D", t1}};
    for (const sm::StageTime& x : sm::stage_times(r2.stats)) st.stages.push_back(x);
    std::printf("  ours: 1D %.3f s CPU (%.3f wall; %llu edges, %u repair splits), 2D %.3f s CPU (%.3f wall: boundary "
                "%.3f, refine %.3f, smooth %.3f, output %.3f): %.0f triangles/s CPU in 2D, %zu warnings\n",
                c1, t1, static_cast<unsigned long long>(r1.stats.edges), r1.stats.repair_splits, c2, t2,
                r2.stats.seconds_boundary, r2.stats.seconds_refine, r2.stats.seconds_smooth, r2.stats.seconds_output,
                static_cast<double>(st.triangles) / c2, r2.notes.size());
    print_stats("ours", st);
    std::printf("%s", sm::format_stats(st).c_str());
    ours_1d[a] = c1, ours_2d[a] = c2;
    if (!out_msh.empty()) {
      std::string err;
      sm::io::MshOptions mo;
      mo.save_all = true;
      if (!sm::io::save_msh(sm::io::from_model_mesh(model, r1.mesh), mo, out_msh, &err))
        return std::fprintf(stderr, "%s: %s\n", out_msh.c_str(), err.c_str()), 1;
      std::printf("  wrote %s\n", out_msh.c_str());
    }
    for (std::size_t k = 0; k < r2.notes.size() && k < 3; ++k)
      std::printf("  warning: surface %d: %s\n", r2.notes[k].surface, sm::mesh_note_kind_name(r2.notes[k].kind));
    if (!thread_counts.empty()) {
      if (part_triangles > 0) {
        o2.partition.part_triangles = static_cast<std::uint64_t>(part_triangles);
        o2.partition.min_triangles = 2 * o2.partition.part_triangles;
      }
      sm::Mesh1dResult again = sm::mesh_curves(model, o1);
      thread_table(model, again, o2, thread_counts, target);
    }
  }

  if (!with_gmsh) return 0;
  if (std::system("command -v gmsh >/dev/null 2>&1") != 0) {
    std::printf("gmsh: not installed, its column is skipped\n");
    return 0;
  }
  sm::coast::GshhsPluginOptions po;
  po.radius = radius;
  const std::string geo = sm::coast::write_gshhs_plugin_geo(*cm, po);
  for (int a : list) {
    const std::string base = "/tmp/sm_bench_world_ocean_" + std::to_string(a);
    {
      std::ofstream out(base + ".geo");
      out << geo;
      out << "Field[IFI + 1] = Threshold;\nField[IFI + 1].IField = IFI + 0;\n";
      out << "Field[IFI + 1].LcMin = " << kLcMin / size_scale << ";\nField[IFI + 1].LcMax = " << kLcMax / size_scale
          << ";\n";
      out << "Field[IFI + 1].DistMin = " << kDistMin << ";\nField[IFI + 1].DistMax = " << kDistMax << ";\n";
      out << "Background Field = IFI + 1;\n";
      out << "Mesh.CharacteristicLengthExtendFromBoundary = 0;\nMesh.CharacteristicLengthFromPoints = 0;\n";
      out << "Mesh.CharacteristicLengthFromCurvature = 0;\nMesh.Algorithm = " << a << ";\n";
    }
    const std::string cmd = "gmsh -2 -nt 1 -format msh22 -o " + base + ".msh " + base + ".geo 2>&1";
    t0 = std::chrono::steady_clock::now();
    FILE* p = popen(cmd.c_str(), "r");
    std::string log;
    char buf[4096];
    while (p && std::fgets(buf, sizeof buf, p)) log += buf;
    const int rc = p ? pclose(p) : -1;
    const double wall = since(t0);
    std::printf("gmsh 4.8.4 -algo %d (%s), -nt 1: exit %d, %.3f s wall in all; 1D %.3f s CPU, 2D %.3f s CPU\n", a,
                algo_name(a), rc, wall, gmsh_stage(log, "1D", true), gmsh_stage(log, "2D", true));
    sm::ModelMesh gm;
    if (rc != 0 || !read_msh22(base + ".msh", gm)) {
      std::printf("  gmsh failed; last output:\n%s\n", log.substr(log.size() > 2000 ? log.size() - 2000 : 0).c_str());
      continue;
    }
    print_stats("gmsh", sm::mesh_stats(gm, target));
    const double g1 = gmsh_stage(log, "1D", true), g2 = gmsh_stage(log, "2D", true);
    if (g1 > 0 && g2 > 0)
      std::printf("  CPU ratio gmsh / ours: 1D %.1fx, 2D %.1fx\n", g1 / ours_1d[a], g2 / ours_2d[a]);
  }
  return 0;
}
