// Writes a GSHHG coastline model as the Gmsh-readable .geo of Plugin(GSHHS) (coast module's
// write_gshhs_plugin_geo), so that stereomesh and Gmsh 4.8.4 mesh the same input in
// tests/bench/run.sh. The import is the one of the Coastline statement (the file's own -R box
// closes a regional coast), with a constant accuracy gamma.
// Usage: bench_coast_geo FILE GAMMA_M OUT.geo [--no-check-splines]
//   FILE: a name under data/gshhg (GMT lon/lat text). The import's B-spline crossing
//   check is on, as in the Coastline statement (CheckSplines = 1): points are put back until
//   no two splines cross, so Gmsh's 1D mesh of the same splines cannot stop on a crossing;
//   --no-check-splines turns it off.
// The shore Distance field's PointsList is rewritten without the points of the region box's
// closing curves (open sea, not coast), as stdlib's ShoreProximity drops them with ShoreBox.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "coast/gshhs_plugin_geo.h"
#include "coast/import.h"
#include "coast/read.h"
#include "geo/sphere.h"

namespace {

// The point tags (offsets from IP) of write_gshhs_plugin_geo's coast points that lie on real
// coast: its numbering is replayed (loops in order; a periodic curve writes all its points, a
// piece all but its last), and the points of open-boundary pieces, with the point ending each
// such piece, are left out. As "{ IP + a : IP + b, ... }" ranges.
std::string coast_points_list(const sm::coast::CoastModel& m) {
  std::vector<bool> keep;
  keep.assign(2, false);   // the sphere's centre and pole
  for (const sm::coast::CoastLoop& loop : m.loops) {
    const std::size_t loop_first = keep.size();
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const sm::coast::CoastCurve& c = m.curves[loop.curves[k]];
      const std::size_t n = c.periodic ? c.uv.size() : c.uv.size() - 1;
      for (std::size_t i = 0; i < n; ++i) keep.push_back(!c.open_boundary);
    }
    // The end point of an open piece is the next piece's first: on the box too.
    std::size_t at = loop_first;
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const sm::coast::CoastCurve& c = m.curves[loop.curves[k]];
      const std::size_t n = c.periodic ? c.uv.size() : c.uv.size() - 1;
      at += n;
      if (c.open_boundary) keep[k + 1 < loop.curves.size() ? at : loop_first] = false;
    }
  }
  std::string out;
  for (std::size_t i = 0; i < keep.size();) {
    if (!keep[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < keep.size() && keep[j + 1]) ++j;
    out += (out.empty() ? "IP + " : ", IP + ") + std::to_string(i) + (j > i ? " : IP + " + std::to_string(j) : "");
    i = j + 1;
  }
  return "{ " + out + " }";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: bench_coast_geo FILE GAMMA_M OUT.geo [--no-check-splines]\n");
    return 2;
  }
  const std::string path = std::string(SM_DATA_DIR) + "/gshhg/" + argv[1];
  const double gamma = std::atof(argv[2]);
  if (!(gamma > 0)) return std::fprintf(stderr, "bench_coast_geo: GAMMA_M must be positive\n"), 2;
  bool check_splines = sm::coast::ImportOptions{}.repair.check_splines;
  for (int i = 4; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-check-splines") == 0) check_splines = false;
    else return std::fprintf(stderr, "bench_coast_geo: unknown option %s\n", argv[i]), 2;
  }
  auto coast = sm::coast::read_coastline(sm::coast::CoastFormat::LonLatText, path);
  if (!coast) return std::fprintf(stderr, "%s\n", coast.error().to_string().c_str()), 1;
  sm::coast::ImportOptions io;
  io.radius = sm::geo::kEarthRadius;
  io.repair.check_splines = check_splines;
  io.gamma = [gamma](std::span<const sm::Vec3>, std::span<double> g) { std::fill(g.begin(), g.end(), gamma); };
  auto cm = sm::coast::build_coast_model(std::move(*coast), io);
  if (!cm) return std::fprintf(stderr, "%s\n", cm.error().to_string().c_str()), 1;
  sm::coast::GshhsPluginOptions po;
  po.radius = sm::geo::kEarthRadius;
  std::ofstream out(argv[3]);
  out << sm::coast::write_gshhs_plugin_geo(*cm, po);
  out << "Field [ IFI + 0].PointsList  = " << coast_points_list(*cm) << ";\n";
  if (!out.flush()) return std::fprintf(stderr, "bench_coast_geo: cannot write %s\n", argv[3]), 1;
  std::size_t points = 0;
  for (const auto& c : cm->curves) points += c.uv.size();
  std::printf("%s at gamma %g m%s: %zu curves, %zu loops, %zu surfaces, %zu control points\n", argv[1], gamma,
              check_splines ? " (spline crossings checked)" : " (splines not checked)", cm->curves.size(),
              cm->loops.size(), cm->surfaces.size(), points);
  return 0;
}
