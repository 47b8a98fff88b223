// Fuzz entry: the quality floor (mesh/quality_floor.h) through the 2D mesher, on random
// plane coasts meshed at one size with a random Mesh.QualityFloor in [0, 0.9].
//
// Input bytes (missing ones read as 0):
//   0      the floor: (byte mod 91) / 100
//   1      the mesh size: 0.03 + 0.25 * byte / 255
//   2      the algorithm: byte mod 3 picks front2d, del2d, meshadapt; (byte / 3) mod 2:
//          the outer loop is B-splines (as coasts are: curve points off the chord, where
//          the floor flips before it splits) of 2 + (byte / 6) mod 4 spans each, else Lines
//   3      n, the outer loop's vertices: 3 + byte mod 38
//   then n pairs (angle step, radius) of the star-shaped outer loop round the origin: the
//   steps (1 + byte) are normalised to a turn, the radii are 0.15 + 0.85 * byte / 255.
//   Close angles with different radii make narrow inlets and sharp corners.
//   then k = byte mod 4 islands, each 3 bytes: its vertex count (3 + byte mod 4), its
//   size (a fraction of what fits) and its gap to the coast (down to 1e-4 of the radius
//   that is free: near-coincident curves, islands in the bays' mouths).
//
// What is checked (abort on a violation, so the fuzzer reports it): the mesher returns
// (a clean error is fine; the fuzzer's timeout catches a floor that does not end), and a
// mesh has every triangle turned the same way with nonzero area, every edge in two
// triangles with opposite directions or in one and on a curve, every curve edge in one
// triangle (the boundary kept), the triangles' area that of the domain (no overlap), no
// internal error of the floor, and a located report for any triangle left below the
// floor.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "exact/predicates.h"
#include "exact/quality.h"
#include "fuzz_floor_entry.h"
#include "geo/model.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"

namespace sm::fuzz {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void floor_violated(const char* what, const std::string& detail = {}) {
  std::fprintf(stderr, "fuzz_floor: invariant violated: %s%s%s\n", what, detail.empty() ? "" : ": ", detail.c_str());
  std::abort();
}

class Bytes {
 public:
  Bytes(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t next() { return i_ < n_ ? d_[i_++] : 0; }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

// Twice the signed area of a closed polygon.
double area2(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
  return a;
}

// A closed loop through `pts` in the model, of Lines (spans = 1) or of B-splines each
// with `spans` of the points as control polygon; returns the loop's tag.
bool add_loop(geo::Model& m, const std::vector<Vec2>& pts, int* loop, int spans = 1) {
  const int p = m.new_point_tag();
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i)
    if (!m.add_point(p + i, {pts[i].x, pts[i].y, 0}, 0.1).ok()) return false;
  std::vector<int> curves;
  for (int i = 0; i < n; i += spans) {
    const int c = m.new_curve_tag();
    std::vector<int> ctrl;
    for (int j = i; j <= std::min(i + spans, n); ++j) ctrl.push_back(p + j % n);
    const geo::CurveKind kind = ctrl.size() == 2 ? geo::CurveKind::Line : geo::CurveKind::BSpline;
    if (!m.add_curve(c, kind, ctrl).ok()) return false;
    curves.push_back(c);
  }
  *loop = m.new_loop_tag();
  return m.add_curve_loop(*loop, curves).ok();
}

// SM_FUZZ_FLOOR_VERBOSE=1: one line per input on stderr (to see what a corpus covers).
bool verbose() {
  static const bool v = std::getenv("SM_FUZZ_FLOOR_VERBOSE") != nullptr;
  return v;
}

// The domain's area from the curves' meshes (the floor's new nodes included), signed: each
// curve is run in its own direction, as the loops use them (islands clockwise, against
// the outer loop, which may run either way when it has none).
double mesh_domain_area(const ModelMesh& mesh) {
  double a2 = 0;
  for (const auto& [tag, cm] : mesh.curves)
    for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) {
      const Vec3 p = mesh.nodes[cm.nodes[k]].xyz, q = mesh.nodes[cm.nodes[k + 1]].xyz;
      a2 += cross(Vec2{p.x, p.y}, Vec2{q.x, q.y});
    }
  return 0.5 * a2;
}

void check_mesh(const ModelMesh& mesh, const Mesh2dResult& r2, double floor, double polygon_area, bool lines) {
  // Lines: the floor's nodes lie on them, so the domain is the input's polygons.
  // (An outer loop whose points span less than half a turn may run clockwise.)
  const double domain_area = std::fabs(mesh_domain_area(mesh));
  if (lines && std::fabs(domain_area - polygon_area) > 1e-9 * polygon_area)
    floor_violated("the boundary moved off its lines",
                   std::to_string(domain_area) + " for " + std::to_string(polygon_area));
  for (const MeshNote& w : r2.notes)
    if (w.kind == MeshNoteKind::FloorFault) floor_violated("the floor reported an internal error", w.fault);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  int sign = 0;
  double area = 0, min_rho = 1;
  for (const auto& [tag, sf] : mesh.surfaces)
    for (const auto& t : sf.triangles) {
      const Vec3 a = mesh.nodes[t[0]].xyz, b = mesh.nodes[t[1]].xyz, c = mesh.nodes[t[2]].xyz;
      const Sign s = orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y});
      if (s == Sign::Zero) floor_violated("a flat triangle");
      const int si = s == Sign::Positive ? 1 : -1;
      if (sign == 0) sign = si;
      if (si != sign) floor_violated("an inverted triangle");
      area += 0.5 * std::fabs(cross(Vec2{b.x - a.x, b.y - a.y}, Vec2{c.x - a.x, c.y - a.y}));
      min_rho = std::min(min_rho, rho(a, b, c));
      for (int e = 0; e < 3; ++e)
        if (++directed[{t[e], t[(e + 1) % 3]}] > 1) floor_violated("two triangles on the same side of an edge");
    }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> on_curve;
  for (const auto& [tag, cm] : mesh.curves)
    for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) ++on_curve[std::minmax(cm.nodes[k], cm.nodes[k + 1])];
  for (const auto& [e, n] : directed) {
    const bool twin = directed.count({e.second, e.first}) > 0;
    if (!twin && !on_curve.count(std::minmax(e.first, e.second))) floor_violated("a boundary edge on no curve");
  }
  for (const auto& [e, n] : on_curve) {
    const int uses = static_cast<int>(directed.count(e) + directed.count({e.second, e.first}));
    if (uses != 1) floor_violated("a curve edge not in exactly one triangle (the boundary lost)");
  }
  if (verbose()) {
    std::size_t n = 0;
    for (const auto& [tag, sf] : mesh.surfaces) n += sf.triangles.size();
    std::fprintf(stderr,
                 "fuzz_floor: floor %.2f: %zu triangles, rho min %.3f, %zu curve splits, %zu points, %zu reports\n",
                 floor, n, min_rho, static_cast<std::size_t>(r2.stats.floor_curve_splits),
                 static_cast<std::size_t>(r2.stats.floor_points), r2.notes.size());
    for (const MeshNote& w : r2.notes)
      std::fprintf(stderr, "  surface %d: %s: %llu triangles, near (%g, %g, %g)\n", w.surface,
                   mesh_note_kind_name(w.kind), static_cast<unsigned long long>(w.count), w.place.xyz.x,
                   w.place.xyz.y, w.place.xyz.z);
  }
  if (std::fabs(area - domain_area) > 1e-9 * domain_area)
    floor_violated("the triangles do not cover the domain once",
                   std::to_string(area) + " for " + std::to_string(domain_area));
  // Below the floor at the end: the floor says so, with a place.
  if (floor > 0 && min_rho < floor - 1e-9) {
    bool reported = false;
    for (const MeshNote& w : r2.notes)
      reported = reported || (w.kind == MeshNoteKind::FloorSharpCorners && !w.corners.empty()) ||
                 w.kind == MeshNoteKind::FloorStillBelow;
    if (!reported) floor_violated("a triangle below the floor and no located report");
  }
}

}  // namespace

void run_floor_input(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const double floor = (in.next() % 91) / 100.0;
  const double mesh_size = 0.03 + 0.25 * in.next() / 255.0;
  const int kinds = in.next();
  const int algo = kinds % 3;
  const int spans = (kinds / 3) % 2 ? 2 + (kinds / 6) % 4 : 1;
  const int n = 3 + in.next() % 38;
  std::vector<double> steps(n), radii(n);
  double turn = 0;
  for (int i = 0; i < n; ++i) {
    steps[i] = 1 + in.next();
    radii[i] = 0.15 + 0.85 * in.next() / 255.0;
    turn += steps[i];
  }
  std::vector<Vec2> outer(n);
  double angle = 0;
  for (int i = 0; i < n; ++i) {
    outer[i] = {radii[i] * std::cos(angle), radii[i] * std::sin(angle)};
    angle += 2 * kPi * steps[i] / turn;
  }
  // The widest angle one curve spans (a B-spline lies in the hull of its control points,
  // a Line is its own): at half a turn or more the origin may lie outside: no islands.
  double max_gap = 0;
  for (int i = 0; i < n; i += spans) {
    double gap = 0;
    for (int j = i; j < std::min(i + spans, n); ++j) gap += 2 * kPi * steps[j] / turn;
    max_gap = std::max(max_gap, gap);
  }
  geo::Model m;
  int outer_loop = 0;
  if (!add_loop(m, outer, &outer_loop, spans)) return;
  double domain = 0.5 * std::fabs(area2(outer));
  std::vector<int> loops = {outer_loop};
  const int k = in.next() % 4;
  if (max_gap < 0.9 * kPi && k > 0) {
    // Free disc round the origin: every outer edge is at least this far from it.
    const double free_r = *std::min_element(radii.begin(), radii.end()) * std::cos(0.5 * max_gap);
    for (int j = 0; j < k; ++j) {
      const int nv = 3 + in.next() % 4;
      const double size_frac = 0.05 + 0.9 * in.next() / 255.0;
      const double gap_frac = std::pow(10.0, -4.0 * in.next() / 255.0);   // 1 .. 1e-4
      // Islands on a ring at angles 2 pi j / k, each within its sector and the free disc.
      double s = size_frac * 0.3 * free_r;
      const double d = k == 1 ? 0 : free_r - s - gap_frac * 0.5 * s;
      if (k > 1 && 2 * d * std::sin(kPi / k) <= 2.2 * s) continue;
      if (k == 1) s = std::min(s, free_r * (1 - 1e-4 - gap_frac * 0.5));
      const double th = 2 * kPi * j / k;
      const Vec2 c{d * std::cos(th), d * std::sin(th)};
      std::vector<Vec2> isl(nv);
      for (int v = 0; v < nv; ++v) {
        const double a = -2 * kPi * v / nv + 0.3;   // clockwise
        isl[v] = {c.x + s * std::cos(a), c.y + s * std::sin(a)};
      }
      int l = 0;
      if (!add_loop(m, isl, &l)) return;
      loops.push_back(l);
      domain -= 0.5 * std::fabs(area2(isl));
    }
  }
  if (!m.add_plane_surface(m.new_surface_tag(), loops).ok()) {
    if (verbose()) std::fprintf(stderr, "fuzz_floor: no surface\n");
    return;
  }
  Mesh1dOptions o1;
  o1.size.from_points = false;
  o1.size.extend_from_boundary = 0;
  o1.size.max = mesh_size;
  Mesh1dResult r1 = mesh_curves(m, o1);
  if (!r1.ok()) {
    if (verbose()) std::fprintf(stderr, "fuzz_floor: 1D failed cleanly\n");
    return;
  }
  ModelMesh mesh = std::move(r1.mesh);
  Mesh2dOptions o2;
  o2.size = o1.size;
  o2.quality_floor = floor;
  o2.algorithm = algo == 0 ? Mesh2dAlgorithm::Frontal : algo == 1 ? Mesh2dAlgorithm::Del2d : Mesh2dAlgorithm::MeshAdapt;
  const Mesh2dResult r2 = mesh_surfaces(m, mesh, o2);
  if (!r2.ok()) {
    if (r2.error.problem == MeshProblem::None && r2.error.kind != MeshErrorKind::LimitExceeded)
      floor_violated("an error naming no problem");
    if (verbose())
      std::fprintf(stderr, "fuzz_floor: 2D failed cleanly: problem %d\n", static_cast<int>(r2.error.problem));
    return;
  }
  check_mesh(mesh, r2, floor, domain, spans == 1);
}

}  // namespace sm::fuzz
