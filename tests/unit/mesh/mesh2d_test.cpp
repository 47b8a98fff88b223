// mesh/mesh2d: faces meshed from their 1D boundary mesh: a square with holes, an annulus,
// a PolarSphere cap and the world ocean of GSHHG crude with a shore-distance size; checks
// topology, boundary edges, orientation, nodes on the sphere, size conformity, determinism.
#include "mesh/mesh2d.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <thread>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "exact/predicates.h"
#include "exact/quality.h"
#include "field/distance.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh_stats.h"
#include "testing_coast.h"

using namespace sm;

namespace {

using Tri = std::array<std::uint32_t, 3>;

// A square of corners (x0, y0) - (x1, y1) as four Lines and a loop; returns the loop tag.
int add_square(geo::Model& m, double x0, double y0, double x1, double y1, double lc, bool ccw) {
  const int p = m.new_point_tag();
  REQUIRE(m.add_point(p, {x0, y0, 0}, lc).ok());
  REQUIRE(m.add_point(p + 1, {x1, y0, 0}, lc).ok());
  REQUIRE(m.add_point(p + 2, {x1, y1, 0}, lc).ok());
  REQUIRE(m.add_point(p + 3, {x0, y1, 0}, lc).ok());
  const int c = m.new_curve_tag();
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(c + i, geo::CurveKind::Line, {p + i, p + (i + 1) % 4}).ok());
  const int l = m.new_loop_tag();
  if (ccw) REQUIRE(m.add_curve_loop(l, {c, c + 1, c + 2, c + 3}).ok());
  else REQUIRE(m.add_curve_loop(l, {-(c + 3), -(c + 2), -(c + 1), -c}).ok());
  return l;
}

// A full circle of four arcs around (cx, cy) (or, on a geometry, in its (u,v) plane).
int add_circle(geo::Model& m, double cx, double cy, double r, double lc) {
  const int p = m.new_point_tag();
  REQUIRE(m.add_point(p, {cx, cy, 0}, lc).ok());
  for (int i = 0; i < 4; ++i) {
    const double a = geo::kPi / 2 * i;
    REQUIRE(m.add_point(p + 1 + i, {cx + r * std::cos(a), cy + r * std::sin(a), 0}, lc).ok());
  }
  const int c = m.new_curve_tag();
  for (int i = 0; i < 4; ++i)
    REQUIRE(m.add_curve(c + i, geo::CurveKind::Circle, {p + 1 + i, p, p + 1 + (i + 1) % 4}).ok());
  const int l = m.new_loop_tag();
  REQUIRE(m.add_curve_loop(l, {c, c + 1, c + 2, c + 3}).ok());
  return l;
}

// A circle of radius r around (u,v) = 0 made of n Lines (straight in (u,v)), on the current
// geometry: on a PolarSphere a circle of latitude, approximated by a polygon in (u,v).
int add_uv_polygon(geo::Model& m, double r, int n, double lc) {
  const int p = m.new_point_tag();
  for (int i = 0; i < n; ++i) {
    const double a = 2 * geo::kPi * i / n;
    REQUIRE(m.add_point(p + i, {r * std::cos(a), r * std::sin(a), 0}, lc).ok());
  }
  const int c = m.new_curve_tag();
  std::vector<int> cs;
  for (int i = 0; i < n; ++i) {
    REQUIRE(m.add_curve(c + i, geo::CurveKind::Line, {p + i, p + (i + 1) % n}).ok());
    cs.push_back(c + i);
  }
  const int l = m.new_loop_tag();
  REQUIRE(m.add_curve_loop(l, cs).ok());
  return l;
}

std::string name_of(Mesh2dAlgorithm a) {
  switch (a) {
    case Mesh2dAlgorithm::Del2d: return "del2d";
    case Mesh2dAlgorithm::Frontal: return "front2d";
    case Mesh2dAlgorithm::MeshAdapt: return "meshadapt";
    default: return "automatic";
  }
}

constexpr Mesh2dAlgorithm kAlgorithms[] = {Mesh2dAlgorithm::Del2d, Mesh2dAlgorithm::Frontal,
                                           Mesh2dAlgorithm::MeshAdapt};

// Quality floor per algorithm: share of triangles with rho > 0.9 on the uniform cases.
double rho09_floor(Mesh2dAlgorithm a) {
  switch (a) {
    case Mesh2dAlgorithm::Frontal: return 0.95;
    case Mesh2dAlgorithm::MeshAdapt: return 0.8;
    default: return 0.8;
  }
}

struct Meshed {
  ModelMesh mesh;
  Mesh2dResult r2;
};

Meshed mesh_model(const geo::Model& m, const Mesh1dOptions& o1, const Mesh2dOptions& o2) {
  Meshed out;
  Mesh1dResult r1 = mesh_curves(m, o1);
  INFO(static_cast<int>(r1.error.problem));
  REQUIRE(r1.ok());
  out.mesh = std::move(r1.mesh);
  out.r2 = mesh_surfaces(m, out.mesh, o2);
  INFO(static_cast<int>(out.r2.error.problem));
  REQUIRE(out.r2.ok());
  return out;
}

// The boundary of a face's loops as undirected node pairs (with multiplicity 1 each);
// loops of fewer than 3 edges (islands below the mesh size) are left out, as mesh2d does.
std::vector<std::pair<std::uint32_t, std::uint32_t>> loop_edges(const geo::Model& m, const ModelMesh& mesh, int surface,
                                                                long* loops_used = nullptr) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  long used = 0;
  for (int l : m.surface(surface)->loops) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> mine;
    for (int c : m.curve_loop(std::abs(l))->curves) {
      const CurveMesh& cm = mesh.curves.at(std::abs(c));
      for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) mine.push_back(std::minmax(cm.nodes[k], cm.nodes[k + 1]));
    }
    if (mine.size() < 3) continue;
    ++used;
    out.insert(out.end(), mine.begin(), mine.end());
  }
  if (loops_used) *loops_used = used;
  std::sort(out.begin(), out.end());
  return out;
}

// Valid topology of one face: every directed edge once, every interior edge seen from
// both sides, the edges seen once are exactly the loop edges, no degenerate triangle,
// and Euler's V - E + T = 1 - holes.
void check_face(const geo::Model& m, const ModelMesh& mesh, int surface) {
  const SurfaceMesh& sf = mesh.surfaces.at(surface);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  std::vector<std::uint32_t> verts;
  for (const Tri& t : sf.triangles) {
    REQUIRE(t[0] != t[1]);
    REQUIRE(t[1] != t[2]);
    REQUIRE(t[0] != t[2]);
    for (int e = 0; e < 3; ++e) {
      verts.push_back(t[e]);
      REQUIRE(++directed[{t[e], t[(e + 1) % 3]}] == 1);
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> once;
  std::size_t undirected = 0;
  for (const auto& [e, n] : directed) {
    const bool back = directed.count({e.second, e.first}) != 0;
    if (!back) once.push_back(std::minmax(e.first, e.second));
    if (!back || e.first < e.second) ++undirected;
  }
  std::sort(once.begin(), once.end());
  long loops = 0;
  CHECK(once == loop_edges(m, mesh, surface, &loops));
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  const long holes = loops - 1;
  CHECK(static_cast<long>(verts.size()) - static_cast<long>(undirected) + static_cast<long>(sf.triangles.size()) ==
        1 - holes);
}

// Planar face in z = 0: every triangle strictly counter-clockwise (exact).
void check_ccw_xy(const ModelMesh& mesh, int surface) {
  std::size_t bad = 0;
  for (const Tri& t : mesh.surfaces.at(surface).triangles) {
    const Vec3 a = mesh.nodes[t[0]].xyz, b = mesh.nodes[t[1]].xyz, c = mesh.nodes[t[2]].xyz;
    if (orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) != Sign::Positive) ++bad;
    CHECK(a.z == 0);
  }
  CHECK(bad == 0);
}

// Sphere face: nodes on the sphere (1e-12 relative), every triangle facing outwards,
// (u,v) of the interior nodes mapping to their 3D position.
void check_on_sphere(const geo::Model& m, const ModelMesh& mesh, int surface, double radius) {
  const SurfaceMesh& sf = mesh.surfaces.at(surface);
  const geo::SurfaceGeometry& g = *m.geometry(m.surface(surface)->geometry);
  double worst = 0;
  for (std::uint32_t v : sf.interior_nodes) {
    worst = std::max(worst, std::abs(norm(mesh.nodes[v].xyz) - radius) / radius);
    REQUIRE(mesh.nodes[v].has_uv);
    CHECK(norm(g.point(mesh.nodes[v].uv) - mesh.nodes[v].xyz) <= 1e-12 * radius);
  }
  CHECK(worst <= 1e-12);
  std::size_t inverted = 0;
  for (const Tri& t : sf.triangles) {
    const Vec3 a = mesh.nodes[t[0]].xyz, b = mesh.nodes[t[1]].xyz, c = mesh.nodes[t[2]].xyz;
    if (!(dot(cross(b - a, c - a), a + b + c) > 0)) ++inverted;
  }
  CHECK(inverted == 0);
}

void check_same(const ModelMesh& a, const ModelMesh& b) {
  REQUIRE(a.nodes.size() == b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) REQUIRE(a.nodes[i].xyz == b.nodes[i].xyz);
  REQUIRE(a.surfaces.size() == b.surfaces.size());
  for (const auto& [tag, s] : a.surfaces) CHECK(s.triangles == b.surfaces.at(tag).triangles);
}

// Threshold on a distance field (Gmsh's Threshold with linear ramp, StopAtDistMax off).
class ThresholdOf : public field::SizeField {
 public:
  ThresholdOf(field::FieldPtr d, double lc_min, double lc_max, double d_min, double d_max)
      : d_(std::move(d)), lc_min_(lc_min), lc_max_(lc_max), d_min_(d_min), d_max_(d_max) {}
  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    d_->eval(pts, h);
    for (double& x : h) {
      const double s = std::clamp((x - d_min_) / (d_max_ - d_min_), 0.0, 1.0);
      x = lc_min_ + s * (lc_max_ - lc_min_);
    }
  }

 private:
  field::FieldPtr d_;
  double lc_min_, lc_max_, d_min_, d_max_;
};

// Statistics of a mesh against the uniform size h.
MeshStats uniform_stats(const ModelMesh& mesh, double h) {
  return mesh_stats(mesh, [h](std::span<const Vec3>, std::span<double> out) { std::fill(out.begin(), out.end(), h); });
}

// The area of surface `tag`'s triangles in 3D (chord triangles on a sphere).
double face_area(const ModelMesh& mesh, int tag) {
  double area = 0;
  for (const Tri& t : mesh.surfaces.at(tag).triangles) {
    const Vec3 p = mesh.nodes[t[0]].xyz, q = mesh.nodes[t[1]].xyz, r = mesh.nodes[t[2]].xyz;
    area += 0.5 * norm(cross(q - p, r - p));
  }
  return area;
}

}  // namespace

TEST_CASE("mesh2d: unit square with a square hole and a circular hole, lc 0.03") {
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.03, true);
  const int h1 = add_square(m, 0.2, 0.2, 0.4, 0.45, 0.03, false);
  const int h2 = add_circle(m, 0.7, 0.6, 0.15, 0.03);
  REQUIRE(m.add_plane_surface(1, {outer, h1, h2}).ok());
  for (Mesh2dAlgorithm alg : kAlgorithms) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    const Meshed a = mesh_model(m, {}, o2);
    check_face(m, a.mesh, 1);
    check_ccw_xy(a.mesh, 1);
    const MeshStats st = uniform_stats(a.mesh, 0.03);
    MESSAGE(name_of(alg) << ": " << format_stats(st));
    // Area of the square minus the holes: 1 - 0.05 - pi 0.15^2 (the circle's polygon is a
    // little smaller).
    const double area = face_area(a.mesh, 1);
    CHECK(area == doctest::Approx(1 - 0.05 - geo::kPi * 0.0225).epsilon(2e-3));
    CHECK(st.triangles > 2000);
    CHECK(st.min_rho > 0.4);
    CHECK(st.share_rho_09 > rho09_floor(alg));
    CHECK(st.share_len_07_14 >= 0.95);
    CHECK(st.len_median == doctest::Approx(1).epsilon(0.15));
    const Meshed b = mesh_model(m, {}, o2);
    check_same(a.mesh, b.mesh);
  }
}

TEST_CASE("mesh2d: annulus graded from the inner circle (sizes extended from the boundary)") {
  geo::Model m;
  const int outer = add_circle(m, 0, 0, 1, 0.08);
  const int inner = add_circle(m, 0, 0, 0.3, 0.02);
  REQUIRE(m.add_plane_surface(1, {outer, inner}).ok());
  const Meshed a = mesh_model(m, {}, {});
  check_face(m, a.mesh, 1);
  check_ccw_xy(a.mesh, 1);
  const SurfaceMesh& sf = a.mesh.surfaces.at(1);
  // Edges near the inner circle are much shorter than near the outer one.
  double near_in = 0, near_out = 0;
  int n_in = 0, n_out = 0;
  for (const Tri& t : sf.triangles)
    for (int e = 0; e < 3; ++e) {
      const Vec3 p = a.mesh.nodes[t[e]].xyz, q = a.mesh.nodes[t[(e + 1) % 3]].xyz;
      const double r = norm(0.5 * (p + q));
      if (r < 0.35) near_in += norm(q - p), ++n_in;
      if (r > 0.95) near_out += norm(q - p), ++n_out;
    }
  REQUIRE(n_in > 0);
  REQUIRE(n_out > 0);
  CHECK(near_in / n_in < 0.5 * near_out / n_out);
  const MeshStats st = mesh_stats(a.mesh);
  MESSAGE(format_stats(st));
  CHECK(st.min_rho > 0.3);
  CHECK(st.mean_rho > 0.85);
}

TEST_CASE("mesh2d: PolarSphere cap bounded by the circle of latitude 30N") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, 1}).ok());
  REQUIRE(m.add_polar_sphere(1, 1, 2).ok());
  // z = (1 - rho^2) / (1 + rho^2) = sin 30: the circle rho = 1/sqrt3 around (u,v) = 0
  // (Circle arcs on a surface are 3D arcs, off the sphere: a polygon in (u,v) instead).
  const double rho = 1 / std::sqrt(3.0);
  const int loop = add_uv_polygon(m, rho, 108, 0.05);
  REQUIRE(m.add_plane_surface(1, {loop}).ok());
  REQUIRE(m.surface(1)->geometry == 1);
  for (Mesh2dAlgorithm alg : kAlgorithms) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    const Meshed a = mesh_model(m, {}, o2);
    check_face(m, a.mesh, 1);
    check_on_sphere(m, a.mesh, 1, 1.0);
    const MeshStats st = uniform_stats(a.mesh, 0.05);
    MESSAGE(name_of(alg) << ": " << format_stats(st));
    // Cap area 2 pi (1 - sin 30) = pi.
    const double area = face_area(a.mesh, 1);
    CHECK(area == doctest::Approx(geo::kPi).epsilon(3e-3));
    CHECK(st.share_len_07_14 >= 0.95);
    CHECK(st.min_rho > 0.4);
    CHECK(st.share_rho_09 > rho09_floor(alg));
    const Meshed b = mesh_model(m, {}, o2);
    check_same(a.mesh, b.mesh);
  }
}

namespace {

// A closed polygon of n Lines around (cx, cy) in the current plane or (u,v) plane.
int add_polygon_at(geo::Model& m, double cx, double cy, double r, int n, double lc) {
  const int p = m.new_point_tag();
  for (int i = 0; i < n; ++i) {
    const double a = 2 * geo::kPi * i / n;
    REQUIRE(m.add_point(p + i, {cx + r * std::cos(a), cy + r * std::sin(a), 0}, lc).ok());
  }
  const int c = m.new_curve_tag();
  std::vector<int> cs;
  for (int i = 0; i < n; ++i) {
    REQUIRE(m.add_curve(c + i, geo::CurveKind::Line, {p + i, p + (i + 1) % n}).ok());
    cs.push_back(c + i);
  }
  const int l = m.new_loop_tag();
  REQUIRE(m.add_curve_loop(l, cs).ok());
  return l;
}

// Partitioning thresholds low enough for a unit-test face of ~20k triangles.
Mesh2dOptions partitioned(Mesh2dOptions o) {
  o.partition.min_triangles = 8000;
  o.partition.part_triangles = 2500;
  return o;
}

// Meshes surface 1 partitioned with 1, 2 and 4 threads from the same 1D mesh: the same
// nodes and triangles each time; returns the 1-thread mesh and its result.
Meshed mesh_threads(const geo::Model& m, const ModelMesh& mesh1d, Mesh2dOptions o2) {
  Meshed a;
  for (int threads : {1, 2, 4}) {
    CAPTURE(threads);
    o2.threads = threads;
    ModelMesh mesh = mesh1d;
    const Mesh2dResult r = mesh_surfaces(m, mesh, o2);
    INFO(static_cast<int>(r.error.problem));
    REQUIRE(r.ok());
    CHECK(r.stats.partitioned_faces == 1);
    if (threads == 1) {
      a.mesh = std::move(mesh);
      a.r2 = r;
    } else {
      check_same(a.mesh, mesh);
      CHECK(r.stats.parts == a.r2.stats.parts);
    }
  }
  return a;
}

}  // namespace

TEST_CASE("mesh2d: lon/lat Sphere face, the box 0-40E x 10-50N, meshed in the Mercator plane") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, 1}).ok());
  REQUIRE(m.add_lonlat_sphere(1, 1, 2).ok());
  const double d = geo::kDegToRad;
  // Lines in (lon, lat): parallels and meridians, so the face is exactly the box.
  REQUIRE(m.add_point(3, {0, 10 * d, 0}, 0.03).ok());
  REQUIRE(m.add_point(4, {40 * d, 10 * d, 0}, 0.03).ok());
  REQUIRE(m.add_point(5, {40 * d, 50 * d, 0}, 0.03).ok());
  REQUIRE(m.add_point(6, {0, 50 * d, 0}, 0.03).ok());
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 3, (i + 1) % 4 + 3}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  REQUIRE(m.surface(1)->geometry == 1);
  for (Mesh2dAlgorithm alg : kAlgorithms) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    const Meshed a = mesh_model(m, {}, o2);
    check_face(m, a.mesh, 1);
    check_on_sphere(m, a.mesh, 1, 1.0);
    const MeshStats st = uniform_stats(a.mesh, 0.03);
    MESSAGE(name_of(alg) << ": " << format_stats(st));
    const double area = face_area(a.mesh, 1);
    // Spherical box: dlon (sin 50 - sin 10); the 1D edges are chords, a little inside.
    CHECK(area == doctest::Approx(40 * d * (std::sin(50 * d) - std::sin(10 * d))).epsilon(3e-3));
    CHECK(st.share_len_07_14 >= 0.95);
    CHECK(st.min_rho > 0.4);
    CHECK(st.share_rho_09 > rho09_floor(alg));
    const Meshed b = mesh_model(m, {}, o2);
    check_same(a.mesh, b.mesh);
    if (alg == Mesh2dAlgorithm::MeshAdapt) continue;
    // In 2 parts (the Mercator plane's conformal factor in the sizes of the cut and of the
    // border points): the same checks, the same mesh on 1, 2, 4 threads.
    o2.partition.min_triangles = 500;
    o2.partition.part_triangles = 550;
    Mesh1dResult r1 = mesh_curves(m, {});
    REQUIRE(r1.ok());
    const Meshed p = mesh_threads(m, r1.mesh, o2);
    CHECK(p.r2.stats.parts == 2);
    check_face(m, p.mesh, 1);
    check_on_sphere(m, p.mesh, 1, 1.0);
    const MeshStats sp = uniform_stats(p.mesh, 0.03);
    MESSAGE(name_of(alg) << " in parts: " << format_stats(sp));
    CHECK(sp.share_len_07_14 >= 0.95);
    CHECK(sp.min_rho > 0.4);
    CHECK(double(sp.triangles) == doctest::Approx(double(st.triangles)).epsilon(0.05));
  }
}

TEST_CASE("mesh2d: a lon/lat Sphere face through a pole is a located error") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, 1}).ok());
  REQUIRE(m.add_lonlat_sphere(1, 1, 2).ok());
  const double d = geo::kDegToRad;
  REQUIRE(m.add_point(3, {0, 60 * d, 0}, 0.2).ok());
  REQUIRE(m.add_point(4, {40 * d, 60 * d, 0}, 0.2).ok());
  REQUIRE(m.add_point(5, {40 * d, 90 * d, 0}, 0.2).ok());
  for (int i = 0; i < 3; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 3, (i + 1) % 3 + 3}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  const Mesh2dResult r2 = mesh_surfaces(m, r1.mesh, {});
  CHECK_FALSE(r2.ok());
  CHECK(r2.error.entities.front() == MeshEntity{2, 1});
  CHECK(r2.error.problem == MeshProblem::FaceAtPole);
  CHECK(r2.error.surface == 1);
  CHECK(r2.error.has_xyz);
  CHECK(r2.error.has_lonlat);
  CHECK(r2.error.where.lat == doctest::Approx(90));
  CHECK(r1.mesh.surfaces.empty());
}

TEST_CASE("mesh2d: embedded point and curve are kept as nodes and edges") {
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.05, true);
  REQUIRE(m.add_point(100, {0.5, 0.5, 0}, 0.01).ok());
  REQUIRE(m.add_point(101, {0.2, 0.8, 0}, 0.05).ok());
  REQUIRE(m.add_point(102, {0.8, 0.8, 0}, 0.05).ok());
  REQUIRE(m.add_curve(100, geo::CurveKind::Line, {101, 102}).ok());
  REQUIRE(m.add_plane_surface(1, {outer}).ok());
  REQUIRE(m.embed(0, {100}, 1).ok());
  REQUIRE(m.embed(1, {100}, 1).ok());
  const Meshed a = mesh_model(m, {}, {});
  const SurfaceMesh& sf = a.mesh.surfaces.at(1);
  const std::uint32_t pn = a.mesh.vertex_node.at(100);
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  bool uses_point = false;
  for (const Tri& t : sf.triangles)
    for (int e = 0; e < 3; ++e) {
      edges.insert(std::minmax(t[e], t[(e + 1) % 3]));
      uses_point |= t[e] == pn;
    }
  CHECK(uses_point);
  CHECK(a.mesh.nodes[pn].xyz == Vec3{0.5, 0.5, 0});
  const CurveMesh& cm = a.mesh.curves.at(100);
  for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k)
    CHECK(edges.count(std::minmax(cm.nodes[k], cm.nodes[k + 1])) == 1);
  check_ccw_xy(a.mesh, 1);
  // Smoothed with the embedded point pinned (no warning), to a good quality.
  CHECK(a.r2.notes.empty());
  const MeshStats st = mesh_stats(a.mesh);
  MESSAGE(format_stats(st));
  CHECK(st.min_rho > 0.3);
  CHECK(st.mean_rho > 0.9);
  // The point's size 0.01 is extended around it: short edges at the point.
  double shortest = 1;
  for (const auto& e : edges)
    if (e.first == pn || e.second == pn)
      shortest = std::min(shortest, norm(a.mesh.nodes[e.first].xyz - a.mesh.nodes[e.second].xyz));
  CHECK(shortest < 0.03);
}


// The world ocean north of 60S on a sphere of radius kR km: the outer loop is a closed
// BSpline near the circle of latitude 60S (a circle around (u,v) = 0); every GSHHG ring
// wholly north of 58S, except those in `dropped`, is a hole: a closed BSpline through its
// vertices, as coastline scripts build them. ring_of_curve maps curve tags to rings.
struct World {
  geo::Model m;
  std::map<int, std::size_t> ring_of_curve;
  std::vector<Vec3> coast;
  std::unique_ptr<field::SizeField> size;   // shore distance 30 to 200 km within 500 km
};

// Sizes from the field only, as ocean scripts set them (no point sizes, no extension).
Mesh1dOptions world_options(const field::SizeField* f) {
  Mesh1dOptions o;
  o.background = f;
  o.size.from_points = false;
  o.size.extend_from_boundary = 0;
  return o;
}

void build_world(World& w, const std::vector<testing::Ring>& rings, const std::set<std::size_t>& dropped, double kR) {
  geo::Model& m = w.m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, kR}).ok());
  REQUIRE(m.add_polar_sphere(1, 1, 2).ok());
  const geo::PolarSphere ps = *m.geometry(1)->polar();
  const Vec2 s60 = ps.param_from_lonlat({0, -60});
  int outer = 0;
  {
    const int p0 = m.new_point_tag();
    std::vector<int> ids;
    for (int k = 0; k < 90; ++k) {
      const double a = 2 * geo::kPi * k / 90;
      REQUIRE(m.add_point(p0 + k, {norm(s60) * std::cos(a), norm(s60) * std::sin(a), 0}).ok());
      ids.push_back(p0 + k);
    }
    ids.push_back(p0);
    const int c = m.new_curve_tag();
    REQUIRE(m.add_curve(c, geo::CurveKind::BSpline, ids).ok());
    outer = m.new_loop_tag();
    REQUIRE(m.add_curve_loop(outer, {c}).ok());
  }
  std::vector<int> loops{outer};
  for (std::size_t ri = 0; ri < rings.size(); ++ri) {
    const testing::Ring& r = rings[ri];
    if (dropped.count(ri) || r.wraps_pole || *std::min_element(r.lat.begin(), r.lat.end()) < -58) continue;
    std::size_t n = r.lon.size();
    if (r.lon[0] == r.lon[n - 1] && r.lat[0] == r.lat[n - 1]) --n;
    if (n < 3) continue;
    const int p0 = m.new_point_tag();
    std::vector<int> ids;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 uv = ps.param_from_lonlat({r.lon[k], r.lat[k]});
      REQUIRE(m.add_point(p0 + static_cast<int>(k), {uv.x, uv.y, 0}).ok());
      w.coast.push_back(ps.from_lonlat({r.lon[k], r.lat[k]}));
      ids.push_back(p0 + static_cast<int>(k));
    }
    ids.push_back(p0);
    const int c = m.new_curve_tag();
    REQUIRE(m.add_curve(c, geo::CurveKind::BSpline, ids).ok());
    w.ring_of_curve[c] = ri;
    const int l = m.new_loop_tag();
    REQUIRE(m.add_curve_loop(l, {c}).ok());
    loops.push_back(l);
  }
  REQUIRE(loops.size() > 400);
  REQUIRE(m.add_plane_surface(1, loops).ok());
}

TEST_CASE("mesh2d: world ocean north of 60S from GSHHG crude, shore distance 30 to 200 km") {
  constexpr double kR = 6371.0;   // km: the test works on a sphere of radius 6371
  std::vector<testing::Ring> rings = testing::read_gshhg(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(rings.size() > 500);
  // BSplines through crude data may cross where islands nearly touch (1D meshing reports
  // them, located): drop the smaller ring of each such pair and rebuild.
  std::set<std::size_t> dropped;
  std::unique_ptr<World> wp;
  for (int round = 0;; ++round) {
    REQUIRE(round < 40);
    wp = std::make_unique<World>();
    build_world(*wp, rings, dropped, kR);
    wp->size = std::make_unique<ThresholdOf>(field::make_distance_field(wp->coast), 30, 200, 0, 500);
    const Mesh1dResult r1 = mesh_curves(wp->m, world_options(wp->size.get()));
    if (r1.ok()) break;
    REQUIRE(r1.error.kind == MeshErrorKind::Intersection);
    std::size_t pick = rings.size();
    for (int c : {r1.error.tag(0), r1.error.tag(1)}) {
      const auto it = wp->ring_of_curve.find(c);
      if (it != wp->ring_of_curve.end() &&
          (pick == rings.size() || rings[it->second].lon.size() < rings[pick].lon.size()))
        pick = it->second;
    }
    REQUIRE(pick < rings.size());
    dropped.insert(pick);
  }
  MESSAGE(dropped.size() << " rings dropped (crossing BSplines)");
  CHECK(dropped.size() <= 20);
  const geo::Model& m = wp->m;
  const field::SizeField& size = *wp->size;
  const Mesh1dOptions o1 = world_options(&size);
  Mesh1dResult r1 = mesh_curves(m, o1);
  REQUIRE(r1.ok());
  // Sizes measured on the sphere: the chord midpoint projected radially.
  const auto target = [&](std::span<const Vec3> pts, std::span<double> h) {
    std::vector<Vec3> on(pts.begin(), pts.end());
    for (Vec3& p : on) p = p * (kR / norm(p));
    size.eval(on, h);
  };
  // meshadapt is left out here to keep the test fast (3.4 s for this face; the cap covers
  // it on the sphere).
  for (Mesh2dAlgorithm alg : {Mesh2dAlgorithm::Del2d, Mesh2dAlgorithm::Frontal}) {
  CAPTURE(name_of(alg));
  Mesh2dOptions o2;
  o2.algorithm = alg;
  o2.background = &size;
  o2.size = o1.size;
  Meshed a;
  a.mesh = r1.mesh;
  a.r2 = mesh_surfaces(m, a.mesh, o2);
  REQUIRE(a.r2.ok());
  check_face(m, a.mesh, 1);
  check_on_sphere(m, a.mesh, 1, kR);
  MeshStats st = mesh_stats(a.mesh, target);
  st.stages = stage_times(a.r2.stats);
  REQUIRE(st.stages.size() == 6);
  CHECK(st.stages[1].name == "2D refine");
  CHECK(st.stages[1].seconds > 0);
  MESSAGE(name_of(alg) << ": " << format_stats(st));
  CHECK(st.triangles > 20000);
  CHECK(st.share_len_07_14 >= 0.95);
  // Poor triangles are where the coastline imposes them (narrow straits, sharp capes,
  // nodes of two curves closer than the size: boundary edges are never split in 2D, as in
  // Gmsh); they are few.
  std::size_t poor = 0;
  for (const Tri& t : a.mesh.surfaces.at(1).triangles)
    if (rho(a.mesh.nodes[t[0]].xyz, a.mesh.nodes[t[1]].xyz, a.mesh.nodes[t[2]].xyz) < 0.3) ++poor;
  MESSAGE(poor << " triangles with rho < 0.3");
  CHECK(static_cast<double>(poor) < 0.002 * static_cast<double>(st.triangles));
  CHECK(st.mean_rho > 0.9);
  CHECK(st.share_rho_09 > (alg == Mesh2dAlgorithm::Frontal ? 0.8 : 0.7));
  ModelMesh again = r1.mesh;
  REQUIRE(mesh_surfaces(m, again, o2).ok());
  check_same(a.mesh, again);
  // Refined in parts (thresholds lowered to this face's size): the same checks, quality
  // close to the whole face's, the same bytes for 1, 2 and 4 threads.
  Mesh2dOptions o2p = partitioned(o2);
  o2p.partition.part_triangles = 10000;   // 8 parts (tests elsewhere cut faces finer)
  const Meshed p = mesh_threads(m, r1.mesh, o2p);
  CHECK(p.r2.stats.parts == 8);
  CHECK(double(p.r2.stats.estimated_triangles) == doctest::Approx(double(st.triangles)).epsilon(0.1));
  check_face(m, p.mesh, 1);
  check_on_sphere(m, p.mesh, 1, kR);
  const MeshStats sp = mesh_stats(p.mesh, target);
  MESSAGE(name_of(alg) << " in " << p.r2.stats.parts << " parts: " << format_stats(sp));
  CHECK(sp.share_len_07_14 >= 0.95);
  CHECK(sp.mean_rho > 0.9);
  CHECK(sp.share_rho_09 > st.share_rho_09 - 0.02);
  CHECK(sp.min_rho >= st.min_rho);   // the poorest triangles are at the coast
  CHECK(double(sp.triangles) == doctest::Approx(double(st.triangles)).epsilon(0.03));
  }
}

TEST_CASE("mesh2d: two faces sharing a curve share its nodes and conform along it") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.05).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.05).ok());
  REQUIRE(m.add_point(3, {1, 1, 0}, 0.05).ok());
  REQUIRE(m.add_point(4, {0, 1, 0}, 0.05).ok());
  REQUIRE(m.add_point(5, {2, 0, 0}, 0.1).ok());
  REQUIRE(m.add_point(6, {2, 1, 0}, 0.1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {2, 3}).ok());   // shared
  REQUIRE(m.add_curve(3, geo::CurveKind::Line, {3, 4}).ok());
  REQUIRE(m.add_curve(4, geo::CurveKind::Line, {4, 1}).ok());
  REQUIRE(m.add_curve(5, geo::CurveKind::Line, {2, 5}).ok());
  REQUIRE(m.add_curve(6, geo::CurveKind::Line, {5, 6}).ok());
  REQUIRE(m.add_curve(7, geo::CurveKind::Line, {6, 3}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_curve_loop(2, {5, 6, 7, -2}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  REQUIRE(m.add_plane_surface(2, {2}).ok());
  for (Mesh2dAlgorithm alg : kAlgorithms) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    const Meshed a = mesh_model(m, {}, o2);
    check_face(m, a.mesh, 1);
    check_face(m, a.mesh, 2);
    check_ccw_xy(a.mesh, 1);
    check_ccw_xy(a.mesh, 2);
    // The union is one conforming mesh: no directed edge twice, the shared curve's edges
    // seen once from each face.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (int s : {1, 2})
      for (const Tri& t : a.mesh.surfaces.at(s).triangles)
        for (int e = 0; e < 3; ++e) REQUIRE(++directed[{t[e], t[(e + 1) % 3]}] == 1);
    const CurveMesh& shared = a.mesh.curves.at(2);
    REQUIRE(shared.nodes.size() > 10);
    for (std::size_t k = 0; k + 1 < shared.nodes.size(); ++k) {
      CHECK(directed.count({shared.nodes[k], shared.nodes[k + 1]}) == 1);
      CHECK(directed.count({shared.nodes[k + 1], shared.nodes[k]}) == 1);
    }
  }
}

TEST_CASE("mesh2d: a face in a tilted plane is meshed in that plane") {
  // The square (0,0,0) (1,0,1) (1,1,1) (0,1,0): the plane x = z.
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.05).ok());
  REQUIRE(m.add_point(2, {1, 0, 1}, 0.05).ok());
  REQUIRE(m.add_point(3, {1, 1, 1}, 0.05).ok());
  REQUIRE(m.add_point(4, {0, 1, 0}, 0.05).ok());
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 1, (i + 1) % 4 + 1}).ok());
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  const Meshed a = mesh_model(m, {}, {});
  check_face(m, a.mesh, 1);
  // Newell normal of the loop: (-1, 0, 1) / sqrt2; every triangle faces that way.
  const Vec3 n{-1 / std::sqrt(2.0), 0, 1 / std::sqrt(2.0)};
  double area = 0;
  for (const Tri& t : a.mesh.surfaces.at(1).triangles) {
    const Vec3 p = a.mesh.nodes[t[0]].xyz, q = a.mesh.nodes[t[1]].xyz, r = a.mesh.nodes[t[2]].xyz;
    const Vec3 c = cross(q - p, r - p);
    CHECK(dot(c, n) > 0.999 * norm(c));
    area += 0.5 * norm(c);
  }
  CHECK(area == doctest::Approx(std::sqrt(2.0)).epsilon(1e-9));
  for (std::uint32_t v : a.mesh.surfaces.at(1).interior_nodes)
    CHECK(std::abs(a.mesh.nodes[v].xyz.x - a.mesh.nodes[v].xyz.z) < 1e-12);
  const MeshStats st = uniform_stats(a.mesh, 0.05);
  CHECK(st.share_len_07_14 >= 0.95);
}

TEST_CASE("mesh2d: a non-planar boundary and an embedded curve crossing the boundary are located errors") {
  {
    geo::Model m;
    REQUIRE(m.add_point(1, {0, 0, 0}, 0.2).ok());
    REQUIRE(m.add_point(2, {1, 0, 0}, 0.2).ok());
    REQUIRE(m.add_point(3, {1, 1, 0.3}, 0.2).ok());
    REQUIRE(m.add_point(4, {0, 1, 0}, 0.2).ok());
    for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(i + 1, geo::CurveKind::Line, {i + 1, (i + 1) % 4 + 1}).ok());
    REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
    REQUIRE(m.add_plane_surface(1, {1}).ok());
    Mesh1dResult r1 = mesh_curves(m, {});
    REQUIRE(r1.ok());
    const Mesh2dResult r2 = mesh_surfaces(m, r1.mesh, {});
    CHECK_FALSE(r2.ok());
    CHECK(r2.error.entities.front() == MeshEntity{2, 1});
    CHECK(r2.error.problem == MeshProblem::FaceNotPlanar);
    CHECK(r2.error.value == 1e-3);   // the share of the size Gmsh's check allows
    CHECK(r2.error.has_xyz);
    CHECK_FALSE(r2.error.has_lonlat);
  }
  {
    geo::Model m;
    const int outer = add_square(m, 0, 0, 1, 1, 0.1, true);
    REQUIRE(m.add_point(100, {0.5, 0.5, 0}, 0.1).ok());
    REQUIRE(m.add_point(101, {1.5, 0.53, 0}, 0.1).ok());
    REQUIRE(m.add_curve(100, geo::CurveKind::Line, {100, 101}).ok());
    REQUIRE(m.add_plane_surface(1, {outer}).ok());
    REQUIRE(m.embed(1, {100}, 1).ok());
    Mesh1dOptions o1;
    o1.repair_intersections = false;   // leave the crossing for 2D to find
    Mesh1dResult r1 = mesh_curves(m, o1);
    REQUIRE(r1.ok());
    const Mesh2dResult r2 = mesh_surfaces(m, r1.mesh, {});
    CHECK_FALSE(r2.ok());
    CHECK(r2.error.entities.front() == MeshEntity{2, 1});
    CHECK(r2.error.problem == MeshProblem::BoundaryEdgesCross);
    CHECK(((r2.error.numbers[0] == 100 && r2.error.numbers[1] != 100) ||
           (r2.error.numbers[1] == 100 && r2.error.numbers[0] != 100)));
    CHECK(r2.error.has_xyz);
    CHECK_FALSE(r2.error.has_lonlat);
    CHECK(r1.mesh.surfaces.empty());
  }
}

// A face meshed in parts (a) against the same face meshed in one piece from the 1D mesh
// mesh1d, both measured at the uniform size lc: quality floors of the algorithm, at most 2
// points of rho > 0.9 lost to the seams, size conformity. Returns {parts, whole}.
std::pair<MeshStats, MeshStats> check_against_whole(const geo::Model& m, const ModelMesh& mesh1d,
                                                    const Mesh2dOptions& o2, const Meshed& a, double lc) {
  const auto size = [lc](std::span<const Vec3>, std::span<double> h) { std::fill(h.begin(), h.end(), lc); };
  const MeshStats st = mesh_stats(a.mesh, size);
  ModelMesh whole = mesh1d;
  REQUIRE(mesh_surfaces(m, whole, o2).ok());
  const MeshStats sw = mesh_stats(whole, size);
  MESSAGE(name_of(o2.algorithm) << ", " << a.r2.stats.parts << " parts: " << format_stats(st)
                                << "\n  whole: " << format_stats(sw));
  CHECK(st.min_rho > 0.4);
  CHECK(st.share_rho_09 > rho09_floor(o2.algorithm));
  CHECK(st.share_rho_09 > sw.share_rho_09 - 0.02);
  CHECK(st.share_len_07_14 >= 0.95);
  return {st, sw};
}

TEST_CASE("mesh2d: a square with holes and embedded entities refined in parts, the same for 1, 2, 4 threads") {
  geo::Model m;
  const double lc = 0.01;
  const int outer = add_square(m, 0, 0, 1, 1, lc, true);
  const int h1 = add_square(m, 0.2, 0.2, 0.4, 0.45, lc, false);
  const int h2 = add_circle(m, 0.7, 0.6, 0.15, lc);
  REQUIRE(m.add_plane_surface(1, {outer, h1, h2}).ok());
  // An embedded curve across the middle (part borders may run along it) and a point.
  REQUIRE(m.add_point(100, {0.1, 0.8, 0}, lc).ok());
  REQUIRE(m.add_point(101, {0.9, 0.9, 0}, lc).ok());
  REQUIRE(m.add_point(102, {0.5, 0.1, 0}, lc).ok());
  REQUIRE(m.add_curve(100, geo::CurveKind::Line, {100, 101}).ok());
  REQUIRE(m.embed(1, {100}, 1).ok());
  REQUIRE(m.embed(0, {102}, 1).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  for (Mesh2dAlgorithm alg : {Mesh2dAlgorithm::Del2d, Mesh2dAlgorithm::Frontal}) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    const Meshed a = mesh_threads(m, r1.mesh, partitioned(o2));
    // Part count as designed: the power of two nearest estimate / 2500.
    CHECK(a.r2.stats.parts == part_count(a.r2.stats.triangles, partitioned(o2).partition));
    CHECK(a.r2.stats.parts >= 4);
    check_face(m, a.mesh, 1);
    check_ccw_xy(a.mesh, 1);
    // The embedded curve's edges and point are in the mesh.
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::set<std::uint32_t> nodes;
    for (const Tri& t : a.mesh.surfaces.at(1).triangles)
      for (int e = 0; e < 3; ++e) edges.insert(std::minmax(t[e], t[(e + 1) % 3])), nodes.insert(t[e]);
    const CurveMesh& emb = a.mesh.curves.at(100);
    for (std::size_t k = 0; k + 1 < emb.nodes.size(); ++k)
      CHECK(edges.count(std::minmax(emb.nodes[k], emb.nodes[k + 1])) == 1);
    CHECK(nodes.count(a.mesh.vertex_node.at(102)) == 1);
    const auto [st, sw] = check_against_whole(m, r1.mesh, o2, a, lc);
    CHECK(double(st.triangles) == doctest::Approx(double(sw.triangles)).epsilon(0.03));
  }
}

// A uniform size field (sizes from it alone, as ocean scripts set them).
class ConstantSize : public field::SizeField {
 public:
  explicit ConstantSize(double h) : h_(h) {}
  void eval(std::span<const Vec3>, std::span<double> h) const override { std::fill(h.begin(), h.end(), h_); }

 private:
  double h_;
};

TEST_CASE("mesh2d: a PolarSphere cap with islands refined in parts, the same for 1, 2, 4 threads") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, 1}).ok());
  REQUIRE(m.add_polar_sphere(1, 1, 2).ok());
  const double lc = 0.02;
  std::vector<int> loops{add_uv_polygon(m, 1 / std::sqrt(3.0), 60, lc)};
  // Islands of various sizes (in (u,v); the map is conformal, so they stay round).
  const double islands[][3] = {{0.2, 0.1, 0.08}, {-0.25, 0.2, 0.05}, {0.05, -0.3, 0.1}, {-0.1, -0.05, 0.03},
                               {0.35, -0.2, 0.04}};
  for (const auto& is : islands) loops.push_back(add_polygon_at(m, is[0], is[1], is[2], 12, lc));
  REQUIRE(m.add_plane_surface(1, loops).ok());
  const ConstantSize field(lc);
  const Mesh1dOptions o1 = world_options(&field);
  Mesh1dResult r1 = mesh_curves(m, o1);
  REQUIRE(r1.ok());
  for (Mesh2dAlgorithm alg : {Mesh2dAlgorithm::Del2d, Mesh2dAlgorithm::Frontal}) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    o2.background = &field;
    o2.size = o1.size;
    const Meshed a = mesh_threads(m, r1.mesh, partitioned(o2));
    CHECK(a.r2.stats.parts >= 4);
    check_face(m, a.mesh, 1);
    check_on_sphere(m, a.mesh, 1, 1.0);
    check_against_whole(m, r1.mesh, o2, a, lc);
  }
}

TEST_CASE("mesh2d: statistics against the target sizes the mesher aimed at (extension from the boundary)") {
  // A square with lc 0.03 at its points: Gmsh's extension from the boundary (on by
  // default) sets the size inside, the size policy alone would say the model's size.
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.03, true);
  REQUIRE(m.add_plane_surface(1, {outer}).ok());
  const Meshed a = mesh_model(m, {}, {});
  REQUIRE(a.r2.target_sizes.size() == 1);
  CHECK(a.r2.target_sizes[0].surface == 1);
  const MeshStats st = mesh_stats(a.mesh, a.r2.target_sizes);
  const MeshStats uniform = uniform_stats(a.mesh, 0.03);
  MESSAGE(format_stats(st));
  CHECK(st.len_median == doctest::Approx(1).epsilon(0.1));
  CHECK(st.share_len_07_14 >= 0.95);
  CHECK(st.edges == uniform.edges);
  // The boundary edges are about 0.03 long, so the extended size is about that and the
  // figures are those of the uniform size to within 3%.
  CHECK(st.len_median == doctest::Approx(uniform.len_median).epsilon(0.03));
  // Without the extension the target is the policy's alone, here Mesh.MeshSizeMax 0.05
  // (points' sizes off): the edges aim at it and read ~1 against it.
  Mesh2dOptions o2;
  o2.size.extend_from_boundary = 0;
  o2.size.from_points = false;
  o2.size.max = 0.05;
  const Meshed b = mesh_model(m, {}, o2);
  const MeshStats sb = mesh_stats(b.mesh, b.r2.target_sizes);
  CHECK(sb.len_median == doctest::Approx(1).epsilon(0.15));
}

namespace {

// Records stages and their nesting, and the threads that call it.
class NestingProgress final : public Progress {
 public:
  struct Stage {
    std::string name;
    std::uint64_t total = 0;
    std::size_t depth = 0;
    std::vector<std::uint64_t> updates;
    bool ended = false;
  };
  std::vector<Stage> stages;
  std::vector<std::size_t> open;   // indices into stages
  bool stray = false, other_thread = false;
  std::thread::id caller = std::this_thread::get_id();

  void begin(std::string_view name, std::uint64_t total) override {
    seen();
    stages.push_back({std::string(name), total, open.size(), {}, false});
    open.push_back(stages.size() - 1);
  }
  void update(std::uint64_t done) override {
    seen();
    if (open.empty()) stray = true;
    else stages[open.back()].updates.push_back(done);
  }
  void end() override {
    seen();
    if (open.empty()) stray = true;
    else stages[open.back()].ended = true, open.pop_back();
  }

 private:
  void seen() { other_thread = other_thread || std::this_thread::get_id() != caller; }
};

}  // namespace

TEST_CASE("mesh2d: a face refined in parts reports a nested '2D refine' stage, one unit per part") {
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.01, true);
  REQUIRE(m.add_plane_surface(1, {outer}).ok());
  const int small = add_square(m, 2, 0, 2.1, 0.1, 0.05, true);
  REQUIRE(m.add_plane_surface(2, {small}).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    NestingProgress p;
    Mesh2dOptions o2 = partitioned({});
    o2.threads = threads;
    o2.progress = &p;
    ModelMesh mesh = r1.mesh;
    const Mesh2dResult r = mesh_surfaces(m, mesh, o2);
    REQUIRE(r.ok());
    REQUIRE(r.stats.partitioned_faces == 1);   // the small face is refined in one piece
    CHECK_FALSE(p.stray);
    CHECK_FALSE(p.other_thread);
    CHECK(p.open.empty());
    REQUIRE(p.stages.size() == 2);
    CHECK(p.stages[0].name == "2D");
    CHECK(p.stages[0].depth == 0);
    CHECK(p.stages[0].updates == std::vector<std::uint64_t>{1, 2});
    const NestingProgress::Stage& nested = p.stages[1];
    CHECK(nested.name == "2D refine");
    CHECK(nested.depth == 1);
    CHECK(nested.ended);
    CHECK(nested.total == r.stats.parts);
    REQUIRE(!nested.updates.empty());
    CHECK(nested.updates.front() == 0);
    CHECK(nested.updates.back() == r.stats.parts);
    CHECK(std::is_sorted(nested.updates.begin(), nested.updates.end()));
  }
}

TEST_CASE("mesh2d: a large face refined in one piece reports '2D refine' in estimated triangles") {
  // lc 0.003 on the unit square (~250k triangles), partitioning off: one piece, the
  // refiner telling the triangle count every 64k insertions.
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.003, true);
  REQUIRE(m.add_plane_surface(1, {outer}).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  NestingProgress p;
  Mesh2dOptions o2;
  o2.partition.min_triangles = 0;
  o2.progress = &p;
  ModelMesh mesh = r1.mesh;
  const Mesh2dResult r = mesh_surfaces(m, mesh, o2);
  REQUIRE(r.ok());
  CHECK(r.stats.partitioned_faces == 0);
  CHECK_FALSE(p.stray);
  CHECK_FALSE(p.other_thread);
  REQUIRE(p.stages.size() == 2);
  const NestingProgress::Stage& nested = p.stages[1];
  CHECK(nested.name == "2D refine");
  CHECK(nested.depth == 1);
  CHECK(nested.ended);
  CHECK(double(nested.total) == doctest::Approx(double(r.stats.triangles)).epsilon(0.1));
  // At least one report from inside the refiner, then the end.
  REQUIRE(nested.updates.size() >= 2);
  CHECK(nested.updates.front() >= 65536);
  CHECK(nested.updates.back() == nested.total);
  CHECK(std::is_sorted(nested.updates.begin(), nested.updates.end()));
  // The mesh does not depend on who listens.
  ModelMesh quiet = r1.mesh;
  o2.progress = nullptr;
  REQUIRE(mesh_surfaces(m, quiet, o2).ok());
  check_same(mesh, quiet);
}

TEST_CASE("mesh2d: islands below the mesh size give one warning per surface, naming the largest") {
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.1, true);
  // Three closed B-splines of 4 control points, far below the size 0.1: each gets
  // 2 mesh edges and is left out. The one at (0.7, 0.3) is the widest.
  std::vector<int> loops{outer};
  const double centres[3][3] = {{0.3, 0.3, 0.004}, {0.7, 0.3, 0.012}, {0.5, 0.7, 0.006}};
  for (const auto& c : centres) {
    const int p = m.new_point_tag();
    for (int i = 0; i < 4; ++i) {
      const double a = geo::kPi / 2 * i;
      REQUIRE(m.add_point(p + i, {c[0] + c[2] * std::cos(a), c[1] + c[2] * std::sin(a), 0}, 0.1).ok());
    }
    const int cv = m.new_curve_tag();
    REQUIRE(m.add_curve(cv, geo::CurveKind::BSpline, {p, p + 1, p + 2, p + 3, p}).ok());
    const int l = m.new_loop_tag();
    REQUIRE(m.add_curve_loop(l, {cv}).ok());
    loops.push_back(l);
  }
  REQUIRE(m.add_plane_surface(1, loops).ok());
  const Meshed a = mesh_model(m, {}, {});
  REQUIRE(a.r2.notes.size() == 1);
  const MeshNote& w = a.r2.notes.front();
  CHECK(w.kind == MeshNoteKind::IslandsLeftOut);
  CHECK(w.surface == 1);
  CHECK(w.loops == std::vector<int>{loops[1], loops[2], loops[3]});
  CHECK(!w.place.on_sphere);
  // The largest is the island at (0.7, 0.3): its two nodes' midpoint lies within its radius.
  const double x = w.place.xyz.x, y = w.place.xyz.y;
  CHECK(std::abs(x - 0.7) < 0.013);
  CHECK(std::abs(y - 0.3) < 0.013);
  // The face is meshed without them: its boundary is the square's 40 edges only.
  long used = 0;
  const auto edges = loop_edges(m, a.mesh, 1, &used);
  CHECK(used == 1);
  CHECK(edges.size() == 40);
}

TEST_CASE("mesh2d: the element budget refuses a face from its boundary, before refinement") {
  // A unit square at lc 1e-3 has 4000 boundary nodes and about 2.3e6 triangles: over a
  // budget of 1e5, refused (fast: no triangle is inserted) with the estimate and the limit.
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 1e-3, true);
  REQUIRE(m.add_plane_surface(1, {outer}).ok());
  Mesh1dResult r1 = mesh_curves(m, {});
  REQUIRE(r1.ok());
  for (Mesh2dAlgorithm alg : kAlgorithms) {
    CAPTURE(name_of(alg));
    ModelMesh mesh = r1.mesh;
    Mesh2dOptions o2;
    o2.algorithm = alg;
    o2.max_elements = 1e5;
    const Mesh2dResult r2 = mesh_surfaces(m, mesh, o2);
    REQUIRE_FALSE(r2.ok());
    CHECK(r2.error.entities.front() == MeshEntity{2, 1});
    CHECK(r2.error.kind == MeshErrorKind::LimitExceeded);
    CHECK(r2.error.count == doctest::Approx(1 / (1e-6 * std::sqrt(3) / 4)).epsilon(0.05));
    CHECK(r2.error.limit == 1e5);
    CHECK(r2.stats.inserted == 0);
    CHECK(mesh.surfaces.empty());
  }
}

TEST_CASE("mesh2d: within the element budget the mesh is the same as without one") {
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 0.05, true);
  const int hole = add_circle(m, 0.5, 0.5, 0.2, 0.05);
  REQUIRE(m.add_plane_surface(1, {outer, hole}).ok());
  for (Mesh2dAlgorithm alg : kAlgorithms) {
    CAPTURE(name_of(alg));
    Mesh2dOptions o2;
    o2.algorithm = alg;
    const Meshed a = mesh_model(m, {}, o2);
    o2.max_elements = 2.0 * static_cast<double>(a.r2.stats.triangles);
    const Meshed b = mesh_model(m, {}, o2);
    check_same(a.mesh, b.mesh);
    CHECK(a.r2.stats.size_evaluations == b.r2.stats.size_evaluations);
  }
}

TEST_CASE("mesh2d: check_face_budgets estimates faces on a coarse boundary, skipping what it cannot triangulate") {
  // The size field asks for 1e-6 everywhere: 1e6 nodes per side, 2.3e12 triangles. On the
  // coarse 1D mesh (kCoarseCurveNodes per curve) the estimate is the same and cheap.
  class Uniform : public field::SizeField {
   public:
    void eval(std::span<const Vec3>, std::span<double> h) const override {
      for (double& x : h) x = 1e-6;
    }
  } uniform;
  geo::Model m;
  const int outer = add_square(m, 0, 0, 1, 1, 1.0, true);
  REQUIRE(m.add_plane_surface(1, {outer}).ok());
  Mesh1dOptions o1;
  o1.background = &uniform;
  o1.max_elements = 1e12;
  ModelMesh coarse;
  std::size_t calls = 0;
  o1.coarse_check = [&](const ModelMesh& c) {
    ++calls;
    coarse = c;
    return false;
  };
  const Mesh1dResult r1 = mesh_curves(m, o1);
  CHECK(r1.error.kind == MeshErrorKind::Stopped);
  REQUIRE(calls == 1);
  CHECK(coarse.curves.size() == 4);
  for (const auto& [tag, cm] : coarse.curves) CHECK(cm.nodes.size() == static_cast<std::size_t>(kCoarseCurveNodes));
  Mesh2dOptions o2;
  o2.background = &uniform;
  o2.max_elements = 1e12;
  const Mesh2dResult b = check_face_budgets(m, coarse, o2);
  REQUIRE_FALSE(b.ok());
  CHECK(b.error.kind == MeshErrorKind::LimitExceeded);
  CHECK(b.error.entities.front() == MeshEntity{2, 1});
  CHECK(b.error.count == doctest::Approx(1 / (1e-12 * std::sqrt(3) / 4)).epsilon(0.05));
  o2.max_elements = 1e13;
  CHECK(check_face_budgets(m, coarse, o2).ok());
  // Below coarse_check_nodes (or without a budget) the check is not called.
  o1.coarse_check_nodes = 1e6;
  o1.max_elements = 1e12;
  calls = 0;
  Mesh1dOptions o1b = o1;
  o1b.background = nullptr;
  CHECK(mesh_curves(m, o1b).ok());
  CHECK(calls == 0);
}
