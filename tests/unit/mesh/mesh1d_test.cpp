// mesh/mesh1d: the size integral and node placement (Gmsh's counts), closed curves, shared
// end points, edge lengths on the sphere against the field, and the paper's repair loop
// (Figure 7: two islands almost touching; a self-intersecting coastline must fail).
#include "mesh/mesh1d.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "geo/curve_length.h"
#include "geo/sphere.h"
#include "exact/predicates.h"

using namespace sm;

namespace {

// h(x) = a + b * (z + 1): smooth, varying along the meridians of the unit sphere.
class LinearZField : public field::SizeField {
 public:
  LinearZField(double a, double b) : a_(a), b_(b) {}
  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = a_ + b_ * (pts[i].z + 1);
  }

 private:
  double a_, b_;
};

Mesh1dOptions fields_only(const field::SizeField* f) {
  Mesh1dOptions o;
  o.repair_all_curves = true;
  o.background = f;
  o.size.from_points = false;
  return o;
}

// A unit PolarSphere (tags 1, 2 for centre and pole) with closed BSplines through the
// given lon/lat control points (degrees), one curve per ring; returns the next point tag.
geo::Model sphere_model() {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, 1}).ok());
  REQUIRE(m.add_polar_sphere(1, 1, 2).ok());
  return m;
}

int add_ring(geo::Model& m, const std::vector<geo::LonLat>& ring) {
  const geo::PolarSphere ps = *m.geometry(1)->polar();
  std::vector<int> ids;
  const int first = m.new_point_tag();
  for (const geo::LonLat& ll : ring) {
    const int t = m.new_point_tag();
    const Vec2 uv = ps.param_from_lonlat(ll);
    REQUIRE(m.add_point(t, {uv.x, uv.y, 0}).ok());
    ids.push_back(t);
  }
  ids.push_back(first);
  const int c = m.new_curve_tag();
  REQUIRE(m.add_curve(c, geo::CurveKind::BSpline, ids).ok());
  return c;
}

std::vector<geo::LonLat> circle_ring(double lon0, double lat0, double r_deg, int n) {
  std::vector<geo::LonLat> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * geo::kPi * i / n;
    out.push_back({lon0 + r_deg * std::cos(a) / std::cos(lat0 * geo::kDegToRad), lat0 + r_deg * std::sin(a)});
  }
  return out;
}

// An island of radius 3 degrees around (lon0, lat0) with a deep bay opening east (its
// head 0.8 degrees from the centre).
std::vector<geo::LonLat> bay_ring(double lon0, double lat0, int n) {
  std::vector<geo::LonLat> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * geo::kPi * i / n - geo::kPi;   // the bay at a = 0, mid-ring
    const double r = 3 - 2.2 * std::exp(-(a / 0.7) * (a / 0.7));
    out.push_back({lon0 + r * std::cos(a) / std::cos(lat0 * geo::kDegToRad), lat0 + r * std::sin(a)});
  }
  return out;
}

bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Sign s1 = orient2d(a, b, c), s2 = orient2d(a, b, d), s3 = orient2d(c, d, a), s4 = orient2d(c, d, b);
  return s1 != Sign::Zero && s2 != Sign::Zero && s1 != s2 && s3 != Sign::Zero && s4 != Sign::Zero && s3 != s4;
}

// Every pair of non-adjacent edges of all curves (brute force): none may cross in (u,v).
std::size_t count_crossings(const ModelMesh& mesh) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& [tag, c] : mesh.curves)
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) edges.push_back({c.nodes[k], c.nodes[k + 1]});
  std::size_t n = 0;
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [c, d] = edges[j];
      if (a == c || a == d || b == c || b == d) continue;
      if (segments_cross(mesh.nodes[a].uv, mesh.nodes[b].uv, mesh.nodes[c].uv, mesh.nodes[d].uv)) ++n;
    }
  return n;
}

}  // namespace

TEST_CASE("mesh1d: a unit segment with lc = 0.5 gives 2 elements (Gmsh's example)") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.5).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.5).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  const Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  const CurveMesh& c = r.mesh.curves.at(1);
  REQUIRE(c.nodes.size() == 3);
  CHECK(c.t[1] == doctest::Approx(0.5).epsilon(1e-9));
  CHECK(r.mesh.nodes[c.nodes[1]].xyz.x == doctest::Approx(0.5));
  CHECK(c.nodes.front() == r.mesh.vertex_node.at(1));
  CHECK(c.nodes.back() == r.mesh.vertex_node.at(2));
  CHECK(r.mesh.nodes.size() == 3);
}

TEST_CASE("mesh1d: graded line from point sizes, shared end point meshed once") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.01).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.1).ok());
  REQUIRE(m.add_point(3, {1, 1, 0}, 0.1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {2, 3}).ok());
  const Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  // a = integral_0^1 dx / (0.01 + 0.09 x) = ln(10) / 0.09 = 25.58 -> N = int(27.57) = 27.
  const CurveMesh& c1 = r.mesh.curves.at(1);
  CHECK(c1.nodes.size() == 27);
  // Edge lengths grow geometrically: each edge is close to the size at its middle.
  for (std::size_t k = 0; k + 1 < c1.nodes.size(); ++k) {
    const double x0 = r.mesh.nodes[c1.nodes[k]].xyz.x, x1 = r.mesh.nodes[c1.nodes[k + 1]].xyz.x;
    const double h = 0.01 + 0.09 * 0.5 * (x0 + x1);
    CHECK((x1 - x0) / h == doctest::Approx(25.58 / 26).epsilon(0.01));
  }
  // a = 10 on the second line: N = int(11.99) = 11.
  CHECK(r.mesh.curves.at(2).nodes.size() == 11);
  CHECK(r.mesh.curves.at(2).nodes.front() == c1.nodes.back());
  CHECK(r.mesh.nodes.size() == 3 + 25 + 9);
}

TEST_CASE("mesh1d: circle arc and Gmsh's minimum node counts") {
  geo::Model m;
  REQUIRE(m.add_point(1, {1, 0, 0}, 0.1).ok());
  REQUIRE(m.add_point(2, {0, 0, 0}, 0.1).ok());
  REQUIRE(m.add_point(3, {0, 1, 0}, 0.1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Circle, {1, 2, 3}).ok());
  Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  // Length pi/2 at lc 0.1: a = 15.708 -> 17 nodes, equally spaced on the arc.
  const CurveMesh& c = r.mesh.curves.at(1);
  REQUIRE(c.nodes.size() == 17);
  for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k)
    CHECK(norm(r.mesh.nodes[c.nodes[k + 1]].xyz - r.mesh.nodes[c.nodes[k]].xyz) ==
          doctest::Approx(2 * std::sin(geo::kPi / 64)).epsilon(1e-6));
  // Huge sizes: the arc keeps int(0.99 + 6 * (pi/2) / (2 pi)) = 2 segments.
  Mesh1dOptions big;
  big.size.min = 100;
  r = mesh_curves(m, big);
  REQUIRE(r.ok());
  CHECK(r.mesh.curves.at(1).nodes.size() == 3);
}

TEST_CASE("mesh1d: integration converges on a BSpline of many control points") {
  geo::Model m = sphere_model();
  std::vector<geo::LonLat> ring;
  for (int i = 0; i < 2000; ++i) {
    const double a = 2 * geo::kPi * i / 2000;
    ring.push_back({20 * std::cos(a) * (1 + 0.1 * std::sin(7 * a)), 45 + 10 * std::sin(a)});
  }
  const int c = add_ring(m, ring);
  const geo::Curve& shape = *m.curve(c)->shape;
  auto unit = [](std::span<const double>, std::span<const geo::Jet3>, std::span<double> h) {
    std::fill(h.begin(), h.end(), 1.0);
  };
  const CurvePrimitive p = integrate_curve(shape, unit);
  // With h = 1 the integral is the arc length (Gauss-Legendre reference).
  CHECK(p.total() == doctest::Approx(geo::curve_length(shape, 0, 1, 4)).epsilon(1e-6));
  CHECK(std::is_sorted(p.t.begin(), p.t.end()));
  CHECK(std::is_sorted(p.a.begin(), p.a.end()));
}

TEST_CASE("mesh1d: BSpline on a PolarSphere follows the size field on the sphere") {
  geo::Model m = sphere_model();
  std::vector<geo::LonLat> ring;
  for (int i = 0; i < 400; ++i) {
    const double a = 2 * geo::kPi * i / 400;
    ring.push_back({-30 + 60 * std::cos(a), 30 * std::sin(a) + 5 * std::sin(9 * a)});
  }
  const int c = add_ring(m, ring);
  const LinearZField f(0.004, 0.02);   // 25 to 265 km on the Earth
  const Mesh1dResult r = mesh_curves(m, fields_only(&f));
  REQUIRE(r.ok());
  const CurveMesh& cm = r.mesh.curves.at(c);
  CHECK(cm.nodes.front() == cm.nodes.back());
  std::size_t good = 0;
  const std::size_t n = cm.num_edges();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 a = r.mesh.nodes[cm.nodes[k]].xyz, b = r.mesh.nodes[cm.nodes[k + 1]].xyz;
    const double len = geo::geodesic_distance_sphere(geo::lonlat_from_sphere(a), geo::lonlat_from_sphere(b), 1.0);
    const Vec3 mid = m.curve(c)->shape->point(0.5 * (cm.t[k] + cm.t[k + 1]));
    const double h = 0.004 + 0.02 * (mid.z + 1);
    if (len / h >= 0.7 && len / h <= 1.4) ++good;
    // (u,v) of each node is the inverse map of its 3D position.
    CHECK(norm(m.geometry(1)->point(r.mesh.nodes[cm.nodes[k]].uv) - a) < 1e-12);
  }
  CHECK(n > 100);
  CHECK(static_cast<double>(good) >= 0.95 * static_cast<double>(n));
  CHECK(count_crossings(r.mesh) == 0);
}

TEST_CASE("mesh1d: two islands almost touching are repaired by splitting (paper Figure 7)") {
  geo::Model m = sphere_model();
  // A small island (radius 0.3 degrees) near the head of a deep bay of a large one, meshed
  // with edges of 2 degrees: the edge across the bay cuts through the small island.
  const int a = add_ring(m, bay_ring(0, 0, 64));
  const int b = add_ring(m, circle_ring(1.4, 0, 0.3, 24));
  const double h = 2.0 * geo::kDegToRad;
  Mesh1dOptions opt;
  opt.repair_all_curves = true;
  opt.size.from_points = false;
  opt.size.max = h;
  Mesh1dOptions no_repair = opt;
  no_repair.repair_intersections = false;
  const Mesh1dResult before = mesh_curves(m, no_repair);
  REQUIRE(before.ok());
  CHECK(count_crossings(before.mesh) > 0);
  const Mesh1dResult r = mesh_curves(m, opt);
  REQUIRE(r.ok());
  CHECK(r.stats.repair_splits > 0);
  CHECK(r.stats.repair_rounds > 1);
  CHECK(count_crossings(r.mesh) == 0);
  // Split nodes lie on their curves: parameters increase and positions match.
  for (int tag : {a, b}) {
    const CurveMesh& cm = r.mesh.curves.at(tag);
    CHECK(cm.nodes.size() > before.mesh.curves.at(tag).nodes.size());
    CHECK(std::is_sorted(cm.t.begin(), cm.t.end()));
    // (End nodes are the model vertex: a periodic B-spline on the sphere does not pass
    // through its first control point, and Gmsh keeps the vertex there too.)
    for (std::size_t k = 1; k + 1 < cm.nodes.size(); ++k)
      CHECK(norm(r.mesh.nodes[cm.nodes[k]].xyz - m.curve(tag)->shape->point(cm.t[k])) < 1e-12);
  }
  // Deterministic: the same model meshes to the same bytes.
  const Mesh1dResult again = mesh_curves(m, opt);
  REQUIRE(again.mesh.nodes.size() == r.mesh.nodes.size());
  for (std::size_t i = 0; i < r.mesh.nodes.size(); ++i) CHECK(again.mesh.nodes[i].xyz == r.mesh.nodes[i].xyz);
}

TEST_CASE("mesh1d: a self-intersecting coastline fails with the curves and the place") {
  geo::Model m = sphere_model();
  // A figure-eight around (10 E, 40 N): the curve crosses itself at its centre.
  std::vector<geo::LonLat> ring;
  for (int i = 0; i < 40; ++i) {
    const double s = 2 * geo::kPi * i / 40;
    ring.push_back({10 + 8 * std::sin(s), 40 + 4 * std::sin(2 * s)});
  }
  const int c = add_ring(m, ring);
  Mesh1dOptions opt;
  opt.repair_all_curves = true;
  opt.size.from_points = false;
  opt.size.max = 0.5 * geo::kDegToRad;
  const Mesh1dResult r = mesh_curves(m, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == MeshErrorKind::Intersection);
  CHECK(r.error.entities == std::vector<MeshEntity>{{1, c}});
  REQUIRE(r.error.has_lonlat);
  CHECK(r.error.where.lon == doctest::Approx(10).epsilon(0.01));
  CHECK(r.error.where.lat == doctest::Approx(40).epsilon(0.01));
  CHECK(r.error.tag(1) == 0);   // one curve: it crosses itself
}

TEST_CASE("mesh1d: two crossing coastlines name both curves") {
  geo::Model m = sphere_model();
  const int a = add_ring(m, circle_ring(0, 0, 1.0, 16));
  const int b = add_ring(m, circle_ring(1.5, 0, 1.0, 16));
  Mesh1dOptions opt;
  opt.repair_all_curves = true;
  opt.size.from_points = false;
  opt.size.max = 0.2 * geo::kDegToRad;
  const Mesh1dResult r = mesh_curves(m, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == MeshErrorKind::Intersection);
  CHECK(std::min(r.error.tag(0), r.error.tag(1)) == a);
  CHECK(std::max(r.error.tag(0), r.error.tag(1)) == b);
  CHECK(r.error.where.lon == doctest::Approx(0.75).epsilon(0.02));
}

TEST_CASE("mesh1d: only curves of surfaces are repaired unless asked") {
  geo::Model m = sphere_model();
  const int a = add_ring(m, circle_ring(0, 0, 1.0, 16));
  const int b = add_ring(m, circle_ring(1.5, 0, 1.0, 16));
  Mesh1dOptions opt;
  opt.size.from_points = false;
  opt.size.max = 0.2 * geo::kDegToRad;
  // Free curves: Gmsh meshes crossing curves without complaint, and so do we.
  CHECK(mesh_curves(m, opt).ok());
  // As holes of a surface they must not cross.
  REQUIRE(m.add_point(m.new_point_tag(), {-1, -1, 0}).ok());
  const int p0 = m.new_point_tag() - 1;
  REQUIRE(m.add_point(p0 + 1, {1, -1, 0}).ok());
  REQUIRE(m.add_point(p0 + 2, {1, 1, 0}).ok());
  REQUIRE(m.add_point(p0 + 3, {-1, 1, 0}).ok());
  const int c0 = m.new_curve_tag();
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_curve(c0 + i, geo::CurveKind::Line, {p0 + i, p0 + (i + 1) % 4}).ok());
  REQUIRE(m.add_curve_loop(1, {c0, c0 + 1, c0 + 2, c0 + 3}).ok());
  REQUIRE(m.add_curve_loop(2, {a}).ok());
  REQUIRE(m.add_curve_loop(3, {b}).ok());
  const geo::GeoStatus st = m.add_plane_surface(1, {1, 2, 3});
  if (!st.ok()) {
    // The geometry kernel may itself refuse overlapping holes; then embed them instead.
    REQUIRE(m.add_plane_surface(1, {1}).ok());
    REQUIRE(m.embed(1, {a, b}, 1).ok());
  }
  const Mesh1dResult r = mesh_curves(m, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == MeshErrorKind::Intersection);
}

TEST_CASE("mesh1d: Bezier node counts as gmsh 4.8.4 (|X'| divided by the degree)") {
  // Control points (3 i / (n-1), 0.3 (i % 2)) at lc 0.1; gmsh 4.8.4 -1 gives these totals
  // (n points + the curve's interior nodes).
  const int expected[] = {32, 18, 14, 12, 12};
  for (int n = 2; n <= 6; ++n) {
    geo::Model m;
    std::vector<int> ids;
    for (int i = 0; i < n; ++i) {
      REQUIRE(m.add_point(i + 1, {3.0 * i / (n - 1), 0.3 * (i % 2), 0}, 0.1).ok());
      ids.push_back(i + 1);
    }
    REQUIRE(m.add_curve(1, geo::CurveKind::Bezier, ids).ok());
    const Mesh1dResult r = mesh_curves(m, {});
    REQUIRE(r.ok());
    CHECK(r.mesh.nodes.size() == static_cast<std::size_t>(expected[n - 2]));
  }
}

TEST_CASE("mesh1d: Gmsh's smoothing limits the size growth along a curve (Mesh.SmoothRatio)") {
  // lc 0.01 -> 1 on a unit line: gmsh 4.8.4 gives 12 nodes with SmoothRatio 1.8 (h grows
  // by sqrt(1.8) - 1 per unit length: a = ln(1 + 34.2) / 0.342 = 10.4) and 6 with 100.
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.01).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  Mesh1dOptions opt;
  Mesh1dResult r = mesh_curves(m, opt);
  REQUIRE(r.ok());
  CHECK(r.mesh.nodes.size() == 12);
  const CurveMesh& c = r.mesh.curves.at(1);
  for (std::size_t k = 1; k + 1 < c.nodes.size(); ++k) {
    // Consecutive edges grow by at most the ratio of a geometric gradation.
    const double e0 = r.mesh.nodes[c.nodes[k]].xyz.x - r.mesh.nodes[c.nodes[k - 1]].xyz.x;
    const double e1 = r.mesh.nodes[c.nodes[k + 1]].xyz.x - r.mesh.nodes[c.nodes[k]].xyz.x;
    CHECK(e1 / e0 < 1.6);
  }
  opt.smooth_ratio = 100;
  r = mesh_curves(m, opt);
  REQUIRE(r.ok());
  CHECK(r.mesh.nodes.size() == 6);
}

TEST_CASE("mesh1d: a lone closed curve's vertex node sits on the curve, as gmsh 4.8.4 writes it") {
  geo::Model m;
  const Vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) REQUIRE(m.add_point(i + 1, p[i], 0.1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::BSpline, {1, 2, 3, 4, 1}).ok());
  Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  // gmsh -1: node 1 at (1/6, 1/6, 0), 33 nodes in all.
  const Vec3 v = r.mesh.nodes[r.mesh.vertex_node.at(1)].xyz;
  CHECK(v.x == doctest::Approx(1.0 / 6));
  CHECK(v.y == doctest::Approx(1.0 / 6));
  CHECK(r.mesh.nodes.size() == 33);
  // A second curve at that vertex pins the node to the point again.
  REQUIRE(m.add_point(5, {0.5, 0.5, 0}, 0.1).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {1, 5}).ok());
  r = mesh_curves(m, {});
  REQUIRE(r.ok());
  CHECK(r.mesh.nodes[r.mesh.vertex_node.at(1)].xyz == Vec3{0, 0, 0});
}

TEST_CASE("mesh1d: nodes closer than 0.3 h to the previous one are filtered out") {
  // A polyline doubling back on itself within one size: the integral along it asks for
  // nodes that end up next to each other in space; Gmsh's filter removes them.
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.1).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.1).ok());
  REQUIRE(m.add_point(3, {1, 0.001, 0}, 0.1).ok());
  REQUIRE(m.add_point(4, {0.5, 0.001, 0}, 0.1).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2, 3, 4}).ok());
  const Mesh1dResult r = mesh_curves(m, {});
  REQUIRE(r.ok());
  const CurveMesh& c = r.mesh.curves.at(1);
  // Without the filter: a = 15.01 -> 16 nodes; nodes on the way back lie next to nodes on
  // the way out but never next to the node just before them, so only the turn is thinned.
  CHECK(c.nodes.size() <= 16);
  for (std::size_t k = 1; k + 1 < c.nodes.size(); ++k)
    CHECK(norm(r.mesh.nodes[c.nodes[k]].xyz - r.mesh.nodes[c.nodes[k - 1]].xyz) >= 0.03 - 1e-12);
}

TEST_CASE("mesh1d: node_count and place_nodes on absurd integrals are errors, never overflows") {
  CurvePrimitive p;
  p.t = {0, 1};
  p.a = {0, 1e20};
  CHECK(node_count(p, 1) == doctest::Approx(1e20));
  CHECK(place_nodes(p, 1).empty());   // beyond kMaxCurveNodes: nothing placed
  CHECK(place_nodes(p, 1, 10).empty());
  p.a = {0, std::numeric_limits<double>::infinity()};
  CHECK_FALSE(std::isfinite(node_count(p, 1)));
  CHECK(place_nodes(p, 1).empty());
  p.a = {0, std::numeric_limits<double>::quiet_NaN()};
  CHECK(std::isnan(node_count(p, 1)));
  CHECK(place_nodes(p, 1).empty());
  // Gmsh's count, and a coarse version capped at max_nodes (still from 0 to 1).
  p.a = {0, 9.5};
  CHECK(node_count(p, 1) == 11);
  CHECK(place_nodes(p, 1).size() == 11);
  const std::vector<double> coarse = place_nodes(p, 1, 4);
  REQUIRE(coarse.size() == 4);
  CHECK(coarse.front() == 0);
  CHECK(coarse.back() == 1);
  CHECK(coarse[1] == doctest::Approx(1.0 / 3));
}

TEST_CASE("mesh1d: a curve or all curves over max_elements are refused before nodes are placed") {
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 0.01).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 0.01).ok());
  REQUIRE(m.add_point(3, {3, 0, 0}, 0.01).ok());
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, geo::CurveKind::Line, {2, 3}).ok());
  Mesh1dOptions o;
  o.max_elements = 150;   // curve 1 gets 101 nodes, curve 2 201
  Mesh1dResult r = mesh_curves(m, o);
  REQUIRE(r.error.kind == MeshErrorKind::LimitExceeded);
  CHECK(r.error.tag(0) == 2);
  CHECK_FALSE(r.error.all_curves);
  CHECK(r.error.count == 201);
  CHECK(r.error.limit == 150);
  CHECK(r.mesh.curves.empty());
  o.max_elements = 250;   // each within, together over
  r = mesh_curves(m, o);
  REQUIRE(r.error.kind == MeshErrorKind::LimitExceeded);
  CHECK(r.error.all_curves);
  CHECK(r.error.tag(0) == 2);
  CHECK(r.error.count == 302);
  o.max_elements = 302;
  r = mesh_curves(m, o);
  REQUIRE(r.ok());
  CHECK(r.mesh.nodes.size() == 301);
  // Without a budget a count beyond what a curve can index is still refused.
  o.max_elements = 0;
  o.size.factor = 1e-20;
  r = mesh_curves(m, o);
  REQUIRE(r.error.kind == MeshErrorKind::LimitExceeded);
  CHECK(r.error.limit == kMaxCurveNodes);
  CHECK(r.error.tag() == 1);
  CHECK(r.error.count == doctest::Approx(1e22).epsilon(0.1));
}
