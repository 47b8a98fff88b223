// mesh/mesh1d on several threads: the curves are integrated and placed in parallel and
// numbered in tag order afterwards, so the 1D mesh is the same for every thread count,
// and a failure names the curve a single thread would name first.
#include "mesh/mesh1d.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "geo/sphere.h"

namespace {

// h = a + b (1 + sin(k x) cos(k y)): wiggles along every ring, so each curve's adaptive
// integral refines differently.
class WavyField : public sm::field::SizeField {
 public:
  void eval(std::span<const sm::Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i)
      h[i] = 0.004 + 0.006 * (1 + std::sin(40 * pts[i].x) * std::cos(30 * pts[i].y));
  }
};

// 1e-9 north of about 30 degrees: a curve reaching there asks for millions of nodes.
bool threads_in_hole(const sm::Vec3& p) { return p.z > 0.5; }
class HoleField : public sm::field::SizeField {
 public:
  void eval(std::span<const sm::Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = threads_in_hole(pts[i]) ? 1e-9 : 0.01;
  }
};

// A unit PolarSphere with `rings` closed B-splines, small circles spread over the sphere.
sm::geo::Model threads_sphere_rings(int rings) {
  sm::geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {0, 0, 1}).ok());
  REQUIRE(m.add_polar_sphere(1, 1, 2).ok());
  const sm::geo::PolarSphere ps = *m.geometry(1)->polar();
  for (int r = 0; r < rings; ++r) {
    const double lon0 = -150 + 300.0 * r / rings, lat0 = -40 + 7.0 * (r % 12);
    std::vector<int> ids;
    const int first = m.new_point_tag();
    const int n = 30 + 7 * (r % 5);
    for (int i = 0; i < n; ++i) {
      const double a = 2 * sm::geo::kPi * i / n;
      const double rad = 2 + 0.5 * std::sin(3 * a + r);
      const sm::geo::LonLat ll{lon0 + rad * std::cos(a) / std::cos(lat0 * sm::geo::kDegToRad),
                               lat0 + rad * std::sin(a)};
      const int t = m.new_point_tag();
      const sm::Vec2 uv = ps.param_from_lonlat(ll);
      REQUIRE(m.add_point(t, {uv.x, uv.y, 0}).ok());
      ids.push_back(t);
    }
    ids.push_back(first);
    REQUIRE(m.add_curve(m.new_curve_tag(), sm::geo::CurveKind::BSpline, ids).ok());
  }
  return m;
}

void check_same_mesh(const sm::ModelMesh& a, const sm::ModelMesh& b) {
  REQUIRE(a.nodes.size() == b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    CHECK(a.nodes[i].xyz == b.nodes[i].xyz);
    CHECK(a.nodes[i].uv == b.nodes[i].uv);
  }
  REQUIRE(a.curves.size() == b.curves.size());
  for (const auto& [tag, c] : a.curves) {
    const sm::CurveMesh& d = b.curves.at(tag);
    CHECK(c.nodes == d.nodes);
    CHECK(c.t == d.t);
  }
}

}  // namespace

TEST_CASE("mesh1d threads: the same nodes, numbering and parameters for 1, 2 and 5 threads") {
  const sm::geo::Model m = threads_sphere_rings(40);
  const WavyField f;
  sm::Mesh1dOptions opt;
  opt.repair_all_curves = true;
  opt.background = &f;
  opt.size.from_points = false;
  opt.threads = 1;
  const sm::Mesh1dResult one = sm::mesh_curves(m, opt);
  REQUIRE(one.ok());
  CHECK(one.mesh.curves.size() == 40);
  CHECK(one.stats.nodes > 2000);
  for (int threads : {2, 5}) {
    CAPTURE(threads);
    opt.threads = threads;
    const sm::Mesh1dResult r = sm::mesh_curves(m, opt);
    REQUIRE(r.ok());
    CHECK(r.stats.size_evaluations == one.stats.size_evaluations);
    check_same_mesh(one.mesh, r.mesh);
  }
}

TEST_CASE("mesh1d threads: of two failing curves the first in tag order is reported, for any count") {
  sm::geo::Model m = threads_sphere_rings(30);
  const HoleField f;
  sm::Mesh1dOptions opt;
  opt.repair_intersections = false;
  opt.max_elements = 1e6;
  opt.background = &f;
  opt.size.from_points = false;
  // Which curves reach into the hole (rings 10, 11, 22, 23: not the first curve).
  std::vector<int> failing;
  for (const auto& [tag, mc] : m.curves())
    for (int i = 0; i <= 200; ++i)
      if (threads_in_hole(mc.shape->point(i / 200.0))) {
        failing.push_back(tag);
        break;
      }
  REQUIRE(failing.size() >= 2);
  CHECK(failing.front() > m.curves().begin()->first);
  for (int threads : {1, 3, 8}) {
    CAPTURE(threads);
    opt.threads = threads;
    const sm::Mesh1dResult r = sm::mesh_curves(m, opt);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error.kind == sm::MeshErrorKind::LimitExceeded);
    CHECK_FALSE(r.error.all_curves);
    CHECK(r.error.tag(0) == failing.front());
  }
}

TEST_CASE("mesh1d threads: the coarse check's mesh, and the mesh beside it, the same for 1, 2 and 3 threads") {
  // The coarse mesh is made on threads (its nodes numbered in plan order between) and the
  // check runs beside the placement: the coarse nodes, parameters and sizes, the final
  // mesh, and a refusal are the same for every count.
  const sm::geo::Model m = threads_sphere_rings(40);
  const WavyField f;
  sm::Mesh1dOptions opt;
  opt.repair_all_curves = true;
  opt.background = &f;
  opt.size.from_points = false;
  opt.max_elements = 1e9;
  opt.coarse_check_nodes = 0;
  bool accept = true;
  sm::ModelMesh coarse;
  int calls = 0;
  opt.coarse_check = [&](const sm::ModelMesh& c) {
    ++calls;
    coarse = c;
    return accept;
  };
  opt.threads = 1;
  const sm::Mesh1dResult one = sm::mesh_curves(m, opt);
  REQUIRE(one.ok());
  REQUIRE(calls == 1);
  const sm::ModelMesh coarse_one = coarse;
  CHECK(coarse_one.nodes.size() > 1000);
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    opt.threads = threads;
    accept = true;
    calls = 0;
    const sm::Mesh1dResult r = sm::mesh_curves(m, opt);
    REQUIRE(r.ok());
    REQUIRE(calls == 1);
    check_same_mesh(one.mesh, r.mesh);
    check_same_mesh(coarse_one, coarse);
    for (const auto& [tag, c] : coarse_one.curves) CHECK(c.h == coarse.curves.at(tag).h);
    accept = false;
    const sm::Mesh1dResult refused = sm::mesh_curves(m, opt);
    CHECK(refused.error.kind == sm::MeshErrorKind::Stopped);
    CHECK(refused.mesh.curves.empty());
  }
}
