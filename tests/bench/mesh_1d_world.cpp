// Benchmark: 1D meshing of the GSHHG intermediate world coastlines
// (world_i_A100.txt) at 10 km on the unit PolarSphere (paper section 3.2). The model is
// built as a script would: coast reader + import pipeline (accuracy gamma), closed
// B-splines through the control points, one Plane Surface (Antarctica's loop outer when
// present) so that the repair loop sees every coastline. Prints the size integration,
// the repair (Delaunay + edge recovery rounds) and the edge lengths on the sphere.
// Usage: bench_mesh_1d_world [size_km=10] [gamma_km...=10 1]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "coast/import.h"
#include "coast/read_lonlat_text.h"
#include "geo/curve_length.h"
#include "geo/model.h"
#include "geo/sphere.h"
#include "io/from_model_mesh.h"
#include "io/msh_writer.h"
#include "mesh/mesh1d.h"
#include "exact/predicates.h"

using namespace sm;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

class ConstantField : public field::SizeField {
 public:
  explicit ConstantField(double h) : h_(h) {}
  void eval(std::span<const Vec3>, std::span<double> h) const override { std::fill(h.begin(), h.end(), h_); }

 private:
  double h_;
};

struct Built {
  geo::Model model;
  std::size_t control_points = 0, largest_curve = 0;
  double seconds = 0;
  bool ok = false;
};

Built build(const std::string& path, double gamma_m, geo::CurveKind kind) {
  Built b;
  const auto t0 = std::chrono::steady_clock::now();
  auto data = coast::read_lonlat_text(path);
  if (!data) {
    std::fprintf(stderr, "%s\n", data.error().to_string().c_str());
    return b;
  }
  coast::ImportOptions o;
  // Coarsened polygons do not cross, but B-splines through them may (at 10 km: near New
  // York, lon -73.9 lat 40.8, which the 1D repair rightly reports); the spline check puts
  // original points back until no two span hulls overlap.
  o.repair.check_splines = true;
  o.gamma = [gamma_m](std::span<const Vec3>, std::span<double> g) { std::fill(g.begin(), g.end(), gamma_m); };
  auto cm = coast::build_coast_model(std::move(*data), o);
  if (!cm) {
    std::fprintf(stderr, "%s\n", cm.error().to_string().c_str());
    return b;
  }
  geo::Model& m = b.model;
  bool ok = m.add_point(1, {0, 0, 0}).ok() && m.add_point(2, {0, 0, 1}).ok() && m.add_polar_sphere(1, 1, 2).ok();
  std::vector<int> curve_tag(cm->curves.size());
  for (std::size_t i = 0; i < cm->curves.size() && ok; ++i) {
    const coast::CoastCurve& c = cm->curves[i];
    std::vector<int> ids;
    for (const Vec2& uv : c.uv) {
      const int t = m.new_point_tag();
      ok = ok && m.add_point(t, {uv.x, uv.y, 0}).ok();
      ids.push_back(t);
    }
    if (c.periodic) ids.push_back(ids.front());
    b.control_points += c.uv.size();
    b.largest_curve = std::max(b.largest_curve, c.uv.size());
    curve_tag[i] = m.new_curve_tag();
    ok = ok && m.add_curve(curve_tag[i], kind, ids).ok();
  }
  std::vector<int> loop_tag(cm->loops.size());
  for (std::size_t l = 0; l < cm->loops.size() && ok; ++l) {
    std::vector<int> curves;
    for (std::uint32_t c : cm->loops[l].curves) curves.push_back(curve_tag[c]);
    loop_tag[l] = m.new_loop_tag();
    ok = ok && m.add_curve_loop(loop_tag[l], curves).ok();
  }
  for (const coast::CoastSurface& s : cm->surfaces) {
    std::vector<int> loops{loop_tag[s.outer]};
    for (std::uint32_t h : s.holes) loops.push_back(loop_tag[h]);
    const geo::GeoStatus st = m.add_plane_surface(m.new_surface_tag(), loops);
    if (!st.ok()) std::fprintf(stderr, "surface: %s\n", geo::summary(st.error()).c_str());
    ok = ok && st.ok();
  }
  b.seconds = seconds_since(t0);
  b.ok = ok;
  return b;
}

// Independent check of a reported intersection: both splines sampled densely (64 points
// per piece) in (u,v) near the place, segments tested pairwise with exact orient2d.
std::size_t sampled_crossings(const geo::Model& m, const MeshError& e) {
  const geo::PolarSphere ps = *m.geometry(1)->polar();
  const Vec2 at = ps.param_from_lonlat(e.where);
  auto samples = [&](int tag) {
    const geo::Curve& c = *m.curve(tag)->shape;
    const int n = 64 * c.pieces();
    std::vector<std::pair<Vec2, Vec2>> segs;
    Vec2 prev = c.eval_uv(0).p;
    for (int i = 1; i <= n; ++i) {
      const Vec2 p = c.eval_uv(static_cast<double>(i) / n).p;
      if (norm(p - at) < 1e-3 || norm(prev - at) < 1e-3) segs.push_back({prev, p});
      prev = p;
    }
    return segs;
  };
  const int ca = e.tag(0), cb = e.tag(1) ? e.tag(1) : e.tag(0);   // one curve: it meets itself
  const auto a = samples(ca), b = samples(cb);
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = ca == cb ? i + 2 : 0; j < b.size(); ++j) {
      const auto [p, q] = a[i];
      const auto [r, s] = b[j];
      const Sign s1 = orient2d(p, q, r), s2 = orient2d(p, q, s), s3 = orient2d(r, s, p), s4 = orient2d(r, s, q);
      n += s1 != Sign::Zero && s2 != Sign::Zero && s1 != s2 && s3 != Sign::Zero && s4 != Sign::Zero && s3 != s4;
    }
  return n;
}

void run_case(const Built& b, const field::SizeField& field, double h, bool repair) {
  Mesh1dOptions opt;
  opt.background = &field;
  opt.size.from_points = false;
  opt.repair_intersections = repair;
  auto t0 = std::chrono::steady_clock::now();
  const Mesh1dResult r = mesh_curves(b.model, opt);
  const double total = seconds_since(t0);
  if (!r.ok()) {
    std::printf("  1D meshing failed after %.2f s: kind %d, problem %d, curve %d\n", total,
                static_cast<int>(r.error.kind), static_cast<int>(r.error.problem), r.error.tag());
    std::printf("  (dense sampling of the splines there: %zu crossing segment pairs)\n",
                sampled_crossings(b.model, r.error));
    return;
  }
  std::printf("  1D mesh: %llu nodes (%zu of them model points), %llu edges\n",
              static_cast<unsigned long long>(r.stats.nodes), r.mesh.vertex_node.size(),
              static_cast<unsigned long long>(r.stats.edges));
  std::printf("  size integration + placement  %7.3f s  (%llu size evaluations)\n", r.stats.seconds_integrate,
              static_cast<unsigned long long>(r.stats.size_evaluations));
  if (repair)
    std::printf("  repair (Delaunay + recovery)  %7.3f s  (%u rounds, %u splits)\n", r.stats.seconds_repair,
                r.stats.repair_rounds, r.stats.repair_splits);
  std::printf("  1D meshing total              %7.3f s\n", total);
  // Edge lengths on the sphere (GeographicLib geodesics) against the size.
  // Islands shorter than a few sizes get Gmsh's minimum of 2 segments, hence short edges:
  // the figure is also given for curves of at least 10 edges.
  std::size_t good = 0, n = 0, good10 = 0, n10 = 0;
  double lo = 1e300, hi = 0, arc_lo = 1e300, arc_hi = 0;
  for (const auto& [tag, c] : r.mesh.curves)
    for (std::size_t k = 1; k + 2 < c.nodes.size(); ++k) {   // interior edges (end nodes are control points)
      const double len = geo::geodesic_distance_sphere(geo::lonlat_from_sphere(r.mesh.nodes[c.nodes[k]].xyz),
                                                       geo::lonlat_from_sphere(r.mesh.nodes[c.nodes[k + 1]].xyz), 1.0);
      const double q = len / h;
      const bool in = q >= 0.7 && q <= 1.4;
      good += in;
      lo = std::min(lo, q), hi = std::max(hi, q);
      ++n;
      if (c.num_edges() >= 10) good10 += in, ++n10;
      const double arc = geo::curve_length(*b.model.curve(tag)->shape, c.t[k], c.t[k + 1], 2) / h;
      arc_lo = std::min(arc_lo, arc), arc_hi = std::max(arc_hi, arc);
    }
  std::printf(
      "  interior edges within [0.7, 1.4] of the size: %.2f%% of %zu (min %.3f, max %.3f); "
      "on curves of >= 10 edges %.2f%% of %zu\n",
      100.0 * good / std::max<std::size_t>(1, n), n, lo, hi, 100.0 * good10 / std::max<std::size_t>(1, n10), n10);
  // Along the curve (arc length between nodes) the edges match the size; the chords above
  // are shorter where coastlines turn sharply within one size.
  std::printf("  arc length between nodes / size: min %.3f, max %.3f\n", arc_lo, arc_hi);
  t0 = std::chrono::steady_clock::now();
  const io::MeshModel mm = io::from_model_mesh(b.model, r.mesh);
  const double t_conv = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const std::string invalid = io::validate_mesh_model(mm);
  std::printf("  validate_mesh_model %.3f s%s\n", seconds_since(t0), invalid.empty() ? "" : (": " + invalid).c_str());
  t0 = std::chrono::steady_clock::now();
  const std::string msh = io::msh_to_string(mm, io::MshOptions{});
  std::printf("  to MeshModel %.3f s, MSH 4.1 text %.3f s (%.1f MB)\n", t_conv, seconds_since(t0), msh.size() / 1e6);
}

}  // namespace

int main(int argc, char** argv) {
  const double size_km = argc > 1 ? std::atof(argv[1]) : 10.0;
  std::vector<double> gammas_km;
  for (int i = 2; i < argc; ++i) gammas_km.push_back(std::atof(argv[i]));
  if (gammas_km.empty()) gammas_km = {10.0, 1.0};
  const std::string path = std::string(SM_DATA_DIR) + "/gshhg/world_i_A100.txt";
  const double h = size_km * 1e3 / geo::kEarthRadius;   // on the unit sphere
  const ConstantField field(h);
  std::printf("mesh_1d_world: %s meshed at %.1f km (unit PolarSphere, constant background field)\n",
              "world_i_A100.txt", size_km);
  struct Case {
    const char* what;
    geo::CurveKind kind;
    bool repair;
  };
  const Case cases[] = {{"closed B-splines, with the repair", geo::CurveKind::BSpline, true},
                        {"closed B-splines, no repair (as gmsh -1)", geo::CurveKind::BSpline, false},
                        {"polylines through the same points, with the repair", geo::CurveKind::Line, true}};
  for (double gamma_km : gammas_km)
    for (const Case& cs : cases) {
      Built b = build(path, gamma_km * 1e3, cs.kind);
      if (!b.ok) return 1;
      std::printf("\ngamma %.1f km, %s: %zu curves, %zu control points (largest curve %zu), model %.2f s\n",
                  gamma_km, cs.what, b.model.curves().size(), b.control_points, b.largest_curve, b.seconds);
      run_case(b, field, h, cs.repair);
    }
  return 0;
}
