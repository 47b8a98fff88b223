// Our curves against Gmsh 4.8.4: for each curve of tests/data/geo/curves_*.geo, Gmsh's 1D
// mesh (MSH 4.1 with Mesh.SaveParametric) gives nodes with the parameter t at which Gmsh
// evaluated its curve; the same curve built here and evaluated at that t must land on the
// node within 1e-9. Also checks derivatives against finite differences of our own points.
#include "geo/curve.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace sm;
using namespace sm::geo;

namespace {

struct GmshNode {
  Vec3 x;
  double t = 0;
};

struct GmshReference {
  std::map<int, Vec3> points;                       // model vertices by tag
  std::map<int, std::vector<GmshNode>> curve_nodes;  // interior nodes of each curve
};

GmshReference read_msh41(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  GmshReference ref;
  std::string line;
  while (std::getline(in, line)) {
    if (line == "$Entities") {
      int np = 0, nc = 0, ns = 0, nv = 0;
      in >> np >> nc >> ns >> nv;
      for (int i = 0; i < np; ++i) {
        int tag = 0;
        Vec3 x;
        int nphys = 0;
        in >> tag >> x.x >> x.y >> x.z >> nphys;
        for (int k = 0; k < nphys; ++k) in >> tag;
        ref.points[tag] = x;
      }
    } else if (line == "$Nodes") {
      std::size_t nblocks = 0, nnodes = 0, lo = 0, hi = 0;
      in >> nblocks >> nnodes >> lo >> hi;
      for (std::size_t b = 0; b < nblocks; ++b) {
        int dim = 0, tag = 0, parametric = 0;
        std::size_t count = 0;
        in >> dim >> tag >> parametric >> count;
        std::vector<std::size_t> ids(count);
        for (auto& id : ids) in >> id;
        for (std::size_t k = 0; k < count; ++k) {
          GmshNode n;
          in >> n.x.x >> n.x.y >> n.x.z;
          if (parametric && dim >= 1)
            for (int d = 0; d < dim; ++d) in >> (d == 0 ? n.t : n.t);
          if (dim == 1) {
            REQUIRE(parametric == 1);
            ref.curve_nodes[tag].push_back(n);
          }
        }
      }
    }
  }
  return ref;
}

struct CurveCase {
  int tag;
  CurveKind kind;
  std::vector<int> points;
  int geometry = 0;   // index into the geometries of the file, 0 = Euclidean
  std::optional<Vec3> normal{};
};

std::vector<int> range(int a, int b) {
  std::vector<int> r;
  for (int i = a; i <= b; ++i) r.push_back(i);
  return r;
}

std::vector<int> closed(std::vector<int> r) {
  r.push_back(r.front());
  return r;
}

Curve build(const CurveCase& cc, const GmshReference& ref, const std::map<int, SurfaceGeometry>& geos) {
  CurveDef d;
  d.kind = cc.kind;
  d.tag = cc.tag;
  d.periodic = cc.points.size() > 2 && cc.points.front() == cc.points.back();
  d.plane_normal = cc.normal;
  if (cc.geometry) d.surface = geos.at(cc.geometry);
  for (int p : cc.points) {
    const Vec3 x = ref.points.at(p);
    d.xyz.push_back(x);
    if (d.surface) d.uv.push_back(d.surface->param(x));
  }
  auto c = Curve::make(d);
  REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : summary(c.error())));
  return *c;
}

// Largest distance between Gmsh's nodes and our curve at Gmsh's t.
double max_deviation(const Curve& c, const std::vector<GmshNode>& nodes) {
  double worst = 0;
  for (const GmshNode& n : nodes) worst = std::max(worst, norm(c.point(n.t) - n.x));
  return worst;
}

void check_derivatives(const Curve& c) {
  const double h = 1e-6;
  for (double t : {0.013, 0.21, 0.377, 0.5001, 0.683, 0.91}) {
    const Jet3 j = c.eval(t);
    const Vec3 fd1 = (c.point(t + h) - c.point(t - h)) / (2 * h);
    const Vec3 fd2 = (c.eval(t + h).d1 - c.eval(t - h).d1) / (2 * h);
    const double s1 = 1 + norm(j.d1), s2 = 1 + norm(j.d2);
    CHECK(norm(j.d1 - fd1) < 1e-6 * s1);
    CHECK(norm(j.d2 - fd2) < 1e-5 * s2);
    const Jet3 r = c.eval(1 - t, true);
    CHECK(norm(r.p - j.p) < 1e-14 * (1 + norm(j.p)));
    CHECK(norm(r.d1 + j.d1) < 1e-12 * s1);
    if (c.on_surface()) {
      const Jet2 u = c.eval_uv(t);
      const Jet3 m = c.surface()->map(u);
      CHECK(norm(m.p - j.p) < 1e-12);
      CHECK(norm(m.d1 - j.d1) < 1e-9 * s1);
      CHECK(norm(m.d2 - j.d2) < 1e-8 * s2);
    }
  }
}

void run_cases(const std::string& file, const std::vector<CurveCase>& cases,
               const std::map<int, SurfaceGeometry>& geos) {
  const GmshReference ref = read_msh41(std::string(SM_TEST_DATA) + "/geo/" + file);
  std::size_t total = 0;
  for (const CurveCase& cc : cases) {
    CAPTURE(file);
    CAPTURE(cc.tag);
    const Curve c = build(cc, ref, geos);
    const auto& nodes = ref.curve_nodes.at(cc.tag);
    REQUIRE(nodes.size() >= 5);
    total += nodes.size();
    CHECK(max_deviation(c, nodes) < 1e-9);
    check_derivatives(c);
  }
  CHECK(total > 500);
}

}  // namespace

TEST_CASE("curves vs Gmsh 4.8.4: Euclidean Line, Spline, BSpline, Bezier, Circle, Ellipse") {
  using K = CurveKind;
  const std::vector<CurveCase> cases = {
      {1, K::Line, {1, 2}},
      {2, K::Line, range(1, 6)},
      {3, K::Spline, range(1, 8)},
      {4, K::Spline, closed(range(1, 6))},
      {5, K::BSpline, range(1, 8)},
      {6, K::BSpline, closed(range(1, 6))},
      {7, K::BSpline, {1, 2}},
      {8, K::BSpline, {1, 2, 3}},
      {9, K::BSpline, {1, 2, 3, 4}},
      {10, K::BSpline, {1, 2, 2, 3, 4, 5, 5, 6}},
      {11, K::Bezier, range(1, 6)},
      {12, K::Circle, {21, 20, 22}},
      {13, K::Circle, {22, 20, 23}},
      {14, K::Circle, {21, 20, 24}},
      {15, K::Circle, {24, 20, 22}, 0, Vec3{0, 0, 1}},
      {16, K::Ellipse, {30, 20, 31}},
      {17, K::Ellipse, {31, 20, 30, 23}},
      {18, K::Ellipse, {32, 20, 30, 23}},
      {19, K::Circle, {41, 40, 42}},
  };
  run_cases("curves_euclid.msh41", cases, {});
}

TEST_CASE("curves vs Gmsh 4.8.4: drawn in (u,v) on PolarSpheres and a lon/lat Sphere") {
  using K = CurveKind;
  const std::map<int, SurfaceGeometry> geos = {
      {1, SurfaceGeometry(PolarSphere({0, 0, 0}, 1.0))},
      {2, SurfaceGeometry(PolarSphere({1, 2, 3}, 2.0))},
      {3, SurfaceGeometry(Sphere({0, 0, 0}, 1.0))},
  };
  const std::vector<CurveCase> cases = {
      {1, K::Line, {1, 2}, 1},
      {2, K::Line, range(1, 8), 1},
      {3, K::Spline, range(1, 8), 1},
      {4, K::Spline, closed(range(1, 8)), 1},
      {5, K::BSpline, range(1, 8), 1},
      {6, K::BSpline, closed(range(1, 8)), 1},
      {7, K::BSpline, {1, 2, 3}, 1},
      {8, K::Bezier, range(1, 6), 1},
      {9, K::BSpline, closed(range(11, 15)), 2},
      {10, K::Spline, range(11, 15), 2},
      {11, K::BSpline, range(21, 25), 3},
      {12, K::Line, {21, 23}, 3},
  };
  run_cases("curves_polar.msh41", cases, geos);
}

TEST_CASE("curves vs Gmsh 4.8.4: real GSHHG coastlines (Great Britain, New Guinea) on a PolarSphere") {
  using K = CurveKind;
  const std::map<int, SurfaceGeometry> geos = {{1, SurfaceGeometry(PolarSphere({0, 0, 0}, 1.0))}};
  const std::vector<CurveCase> cases = {
      {1, K::BSpline, closed(range(10, 74)), 1},
      {2, K::Spline, closed(range(75, 152)), 1},
      {3, K::Line, range(10, 74), 1},
      {4, K::BSpline, range(75, 152), 1},
  };
  run_cases("coast_polar.msh41", cases, geos);
}

TEST_CASE("curves: a PolarSphere Line is a circle arc in (u,v), not a great circle") {
  const PolarSphere ps({0, 0, 0}, 1.0);
  CurveDef d;
  d.kind = CurveKind::Line;
  d.surface = SurfaceGeometry(ps);
  d.uv = {{-0.5, 0.3}, {0.7, 0.3}};
  for (Vec2 p : d.uv) d.xyz.push_back(ps.point(p));
  const Curve c = *Curve::make(d);
  const Vec2 mid = c.eval_uv(0.5).p;
  CHECK(std::abs(mid.x - 0.1) < 1e-15);
  CHECK(std::abs(mid.y - 0.3) < 1e-15);
  const Vec3 x = c.point(0.5);
  CHECK(std::abs(norm(x) - 1) < 1e-15);
  // The great circle through both ends lies in the plane through the origin: our midpoint does not.
  const Vec3 n = cross(d.xyz[0], d.xyz[1]);
  CHECK(std::abs(dot(n / norm(n), x)) > 1e-3);
}

TEST_CASE("curves: construction errors") {
  CurveDef d;
  d.tag = 7;
  d.kind = CurveKind::Line;
  d.xyz = {{0, 0, 0}};
  auto r = Curve::make(d);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().kind == GeoErrorKind::TooFewPoints);
  CHECK(r.error().tags == std::vector<int>{7});
  d.kind = CurveKind::Circle;
  d.xyz = {{1, 0, 0}, {0, 0, 0}, {0, 1.3, 0}};
  r = Curve::make(d);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().kind == GeoErrorKind::NotCocircular);
  d.xyz = {{1, 0, 0}, {0, 0, 0}, {0, 1.2, 0}};   // within Gmsh's 10% tolerance
  CHECK(Curve::make(d).ok());
  d.xyz = {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}};
  CHECK(Curve::make(d).error().kind == GeoErrorKind::CoincidentPoints);
  d.xyz = {{0, 0, 1}, {0, 0, 0}, {0, 0, -1}};    // collinear along the default normal z
  CHECK(Curve::make(d).error().kind == GeoErrorKind::DegenerateArc);
  d.plane_normal = Vec3{1, 0, 0};
  CHECK(Curve::make(d).ok());
  // Same direction from the centre: Gmsh's "Circle or ellipse arc greater than Pi".
  d.plane_normal.reset();
  d.xyz = {{1, 0, 0}, {0, 0, 0}, {1.05, 0, 0}};
  auto full = Curve::make(d);
  REQUIRE_FALSE(full);
  CHECK(full.error().kind == GeoErrorKind::DegenerateArc);
  CHECK(full.error().id == GeoErrorId::CircleFull);
  d.kind = CurveKind::Ellipse;
  d.plane_normal.reset();
  d.xyz = {{2, 0, 0}, {0, 0, 0}, {-2, 0, 0}};    // both on the major axis
  CHECK(Curve::make(d).error().kind == GeoErrorKind::DegenerateArc);
  d.xyz = {{2, 0, 0}, {0, 0, 0}, {3, 1, 0}};     // end farther along the major axis than a
  CHECK(Curve::make(d).error().kind == GeoErrorKind::DegenerateArc);
}

TEST_CASE("curves vs Gmsh 4.8.4: half circles turn +pi about the normal (default +z or Plane)") {
  // Values printed by gmsh 4.8.4 (model.geo.addCircleArc + model.getValue) at t = 0.25, 0.5.
  struct Case {
    Vec3 start, end;
    std::optional<Vec3> normal;
    Vec3 quarter, mid;
  };
  const double h = std::sqrt(0.5);
  const std::vector<Case> cases = {
      {{0, 1, 0}, {0, -1, 0}, std::nullopt, {-h, h, 0}, {-1, 0, 0}},
      {{1, 1, 0}, {-1, -1, 0}, std::nullopt, {0, std::sqrt(2.0), 0}, {-1, 1, 0}},
      {{1, -2, 0.5}, {-1, 2, -0.5}, std::nullopt, {2.15624446, -0.68964473, 0.35355339}, {2.04939015, 1.02469508, 0}},
      {{0, 1, 0}, {0, -1, 0}, Vec3{1, 0, 0}, {0, h, h}, {0, 0, 1}},
      {{0, 1, 0}, {0, -1, 0}, Vec3{-1, 0, 0}, {0, h, -h}, {0, 0, -1}},
      {{3, 0, 0}, {-3, 0, 0}, Vec3{0, 1, 0}, {2.12132034, 0, -2.12132034}, {0, 0, -3}},
  };
  for (const Case& c : cases) {
    CurveDef d;
    d.kind = CurveKind::Circle;
    d.xyz = {c.start, {0, 0, 0}, c.end};
    d.plane_normal = c.normal;
    auto curve = Curve::make(d);
    REQUIRE(curve.ok());
    CHECK(norm(curve->point(0.25) - c.quarter) < 1e-8);
    CHECK(norm(curve->point(0.5) - c.mid) < 1e-8);
    CHECK(norm(curve->point(1.0) - c.end) < 1e-14);
  }
}

TEST_CASE("curves: parameters far outside [0,1] or NaN never overflow the piece index") {
  CurveDef d;
  d.kind = CurveKind::BSpline;
  for (int i = 0; i < 30; ++i) d.xyz.push_back({double(i), 0.5 * i, 0});
  const Curve c = *Curve::make(d);
  for (double t : {1e300, -1e300, 1e18, -7.5, 3.0}) CHECK(std::isfinite(c.point(t).x) == (std::abs(t) < 1e100));
  CHECK(std::isnan(c.point(std::nan("")).x));
  d.xyz.push_back(d.xyz.front());
  d.periodic = true;
  d.kind = CurveKind::Spline;
  const Curve s = *Curve::make(d);
  CHECK(std::isfinite(s.point(-1e9).x));
  CHECK(std::isfinite(s.point(1e9).y));
}
