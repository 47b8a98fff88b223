// The paper's world model on real data (section 2, Fig. 4): every GSHHG crude coastline of
// world_c.txt becomes points in unit-PolarSphere (u,v) coordinates and one closed BSpline;
// Antarctica, the ring round the projection's singular point, is the outer loop of one
// Plane Surface and every other coastline is a hole. The model must accept all of it.
#include "geo/model.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace sm;
using namespace sm::geo;

namespace {

// A tiny reader for the test only (src/coast owns the real one): segments of "lon lat".
struct Segment {
  bool wraps_pole = false;
  std::vector<LonLat> pts;
};

std::vector<Segment> read_segments(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::vector<Segment> segs;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '>') {
      segs.emplace_back();
      segs.back().wraps_pole = line.find("wraps_pole=1") != std::string::npos;
      continue;
    }
    std::istringstream ss(line);
    LonLat p;
    ss >> p.lon >> p.lat;
    REQUIRE(!segs.empty());
    segs.back().pts.push_back(p);
  }
  return segs;
}

}  // namespace

namespace {

// Builds the world model of one GSHHG text export; returns the surface tag.
int build_world(Model& m, const std::vector<Segment>& segs, int& outer, std::vector<int>& holes) {
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {0, 0, 1}));
  REQUIRE(m.add_polar_sphere(1, 1, 2));
  const PolarSphere& ps = *m.geometry(1)->polar();
  for (const Segment& s : segs) {
    std::vector<int> ids;
    for (std::size_t i = 0; i + 1 < s.pts.size(); ++i) {
      const int t = m.new_point_tag();
      const Vec2 uv = ps.param_from_lonlat(s.pts[i]);
      REQUIRE(m.add_point(t, {uv.x, uv.y, 0}));
      ids.push_back(t);
    }
    ids.push_back(ids.front());
    const int c = m.new_curve_tag();
    REQUIRE(m.add_curve(c, CurveKind::BSpline, ids));
    const int l = m.new_loop_tag();
    REQUIRE(m.add_curve_loop(l, {c}));
    if (s.wraps_pole) outer = l;
    else holes.push_back(l);
  }
  std::vector<int> loops{outer};
  loops.insert(loops.end(), holes.begin(), holes.end());
  const int s = m.new_surface_tag();
  const GeoStatus st = m.add_plane_surface(s, loops);
  REQUIRE_MESSAGE(st.ok(), (st.ok() ? "" : summary(st.error())));
  return s;
}

}  // namespace

TEST_CASE("world model: world_l.txt (5,741 low-resolution coastlines) gives one valid face") {
  const std::vector<Segment> segs = read_segments(std::string(SM_DATA_DIR) + "/gshhg/world_l.txt");
  REQUIRE(segs.size() == 5741);
  Model m;
  int outer = 0;
  std::vector<int> holes;
  const int s = build_world(m, segs, outer, holes);
  CHECK(holes.size() == 5740);
  CHECK(m.surface(s)->geometry == 1);
  CHECK(m.curves().size() == 5741);
}

TEST_CASE("world model: world_c.txt as closed BSplines on a PolarSphere, Antarctica outer") {
  const std::vector<Segment> segs = read_segments(std::string(SM_DATA_DIR) + "/gshhg/world_c.txt");
  REQUIRE(segs.size() == 743);
  Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}));
  REQUIRE(m.add_point(2, {0, 0, 1}));
  REQUIRE(m.add_polar_sphere(1, 1, 2));
  const PolarSphere& ps = *m.geometry(1)->polar();
  int outer = 0;
  std::vector<int> holes;
  std::size_t npts = 0;
  for (const Segment& s : segs) {
    std::vector<int> ids;
    const int first = m.new_point_tag();
    for (const LonLat& ll : s.pts) {
      const int t = m.new_point_tag();
      REQUIRE(m.add_point(t, {ps.param_from_lonlat(ll).x, ps.param_from_lonlat(ll).y, 0}));
      ids.push_back(t);
    }
    // The last vertex repeats the first on the sphere (for Antarctica: lon 180 vs -180):
    // close the spline on the first point's tag instead.
    const Vec3 a = m.vertex(ids.front())->xyz, b = m.vertex(ids.back())->xyz;
    REQUIRE(norm(a - b) < 1e-12);
    REQUIRE(m.remove({{0, ids.back()}}, false));
    ids.back() = first;
    npts += ids.size() - 1;
    const int c = m.new_curve_tag();
    REQUIRE(m.add_curve(c, CurveKind::BSpline, ids));
    const int l = m.new_loop_tag();
    REQUIRE(m.add_curve_loop(l, {c}));
    if (s.wraps_pole) {
      CHECK(outer == 0);
      outer = l;
    } else {
      holes.push_back(l);
    }
  }
  CHECK(npts == 7899 - 743);
  REQUIRE(outer != 0);
  std::vector<int> loops{outer};
  loops.insert(loops.end(), holes.begin(), holes.end());
  const int s = m.new_surface_tag();
  auto status = m.add_plane_surface(s, loops);
  REQUIRE_MESSAGE(status.ok(), (status.ok() ? "" : summary(status.error())));
  CHECK(m.surfaces().size() == 1);
  CHECK(m.surface(s)->geometry == 1);
  CHECK(m.surface(s)->loops.size() == 743);
  for (const auto& [t, c] : m.curves()) {
    CHECK(c.periodic());
    CHECK(c.geometry == 1);
    CHECK(c.shape->defined_in_uv());
  }
  // Every boundary curve lies on the unit sphere.
  for (const auto& [t, c] : m.curves())
    for (double u : {0.0, 0.37, 0.91}) CHECK(std::abs(norm(c.shape->point(u)) - 1) < 1e-14);
  // The boundary of the face is every coastline once.
  auto b = m.boundary({{2, s}}, false);
  REQUIRE(b);
  CHECK(b->size() == 743);

  // Antarctica listed after a hole: Gmsh finds the enclosing loop, and so does the model
  // (with a compat note), which makes it the outer loop.
  m.take_compat_notes();
  REQUIRE(m.add_plane_surface(s + 1, {holes.front(), outer}));
  CHECK(m.surface(s + 1)->loops == std::vector<int>{outer, holes.front()});
  CHECK(m.take_compat_notes().size() == 1);
  // Two islands, neither inside the other: no loop encloses the rest, and the error names
  // the loop outside the first one.
  auto bad = m.add_plane_surface(s + 2, {holes[0], holes[1]});
  REQUIRE_FALSE(bad);
  CHECK(bad.error().kind == GeoErrorKind::HoleOutside);
  CHECK(bad.error().tags == std::vector<int>{s + 2, holes[1], holes[0]});
}

TEST_CASE("world_i_A100 coastlines as closed BSplines match gmsh 4.8.4 at its 2,844 curve nodes") {
  // tests/data/geo/world_i_bspline_nodes.txt: "curve t x y z" for every curve node of gmsh's
  // 1D mesh (lc 0.05 on the unit sphere) of the whole file as closed BSplines in Plugin(GSHHS)
  // (u,v) (make_world_geo.py, make_reference.sh). Curve k is segment k; Eurasia (k = 1) has
  // 35,321 control points.
  const std::vector<Segment> segs = read_segments(std::string(SM_DATA_DIR) + "/gshhg/world_i_A100.txt");
  REQUIRE(segs.size() == 1440);
  const PolarSphere ps({0, 0, 0}, 1.0);
  std::vector<Curve> curves;
  curves.reserve(segs.size());
  for (const Segment& s : segs) {
    CurveDef d;
    d.kind = CurveKind::BSpline;
    d.surface = SurfaceGeometry(ps);
    d.periodic = true;
    for (std::size_t i = 0; i + 1 < s.pts.size(); ++i) {
      d.uv.push_back(ps.param_from_lonlat(s.pts[i]));
      d.xyz.push_back(ps.point(d.uv.back()));
    }
    d.uv.push_back(d.uv.front());
    d.xyz.push_back(d.xyz.front());
    auto c = Curve::make(std::move(d));
    REQUIRE(c.ok());
    curves.push_back(std::move(*c));
  }
  CHECK(curves[0].control_uv().size() == 35322);
  std::ifstream in(std::string(SM_TEST_DATA) + "/geo/world_i_bspline_nodes.txt");
  REQUIRE(in.good());
  int k = 0;
  double t = 0, worst = 0;
  Vec3 x;
  std::size_t nodes = 0, on_eurasia = 0;
  while (in >> k >> t >> x.x >> x.y >> x.z) {
    REQUIRE(k >= 1);
    REQUIRE(k <= 1440);
    worst = std::max(worst, norm(curves[k - 1].point(t) - x));
    ++nodes;
    on_eurasia += k == 1;
  }
  CHECK(nodes == 2844);
  CHECK(on_eurasia == 385);
  CHECK(worst < 1e-9);
}
