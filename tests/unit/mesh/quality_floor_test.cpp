// The quality floor (mesh/quality_floor.h) through the 2D mesher: a narrow inlet reaches
// the floor by splitting its sides on their curves; a 5-degree corner is reported with
// its angle, once, and the work stays bounded; faces sharing a split curve stay conforming.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "exact/quality.h"
#include "geo/model.h"
#include "mesh/mesh1d.h"
#include "mesh/mesh2d.h"
#include "mesh/quality_floor.h"
#include "mesh/store_undo.h"

using namespace sm;

namespace {

// A closed polygon of Lines through `pts` (counter-clockwise) as a Plane Surface.
int qf_add_polygon(geo::Model& m, const std::vector<Vec2>& pts, double lc) {
  const int p = m.new_point_tag();
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) REQUIRE(m.add_point(p + i, {pts[i].x, pts[i].y, 0}, lc).ok());
  const int c = m.new_curve_tag();
  std::vector<int> curves;
  for (int i = 0; i < n; ++i) {
    REQUIRE(m.add_curve(c + i, geo::CurveKind::Line, {p + i, p + (i + 1) % n}).ok());
    curves.push_back(c + i);
  }
  const int l = m.new_loop_tag();
  REQUIRE(m.add_curve_loop(l, curves).ok());
  const int s = m.new_surface_tag();
  REQUIRE(m.add_plane_surface(s, {l}).ok());
  return s;
}

// A store's own plane as the floor's space, with no curve to split and no corner: the
// floor can only move, flip and insert inside.
FloorFace qf_flat_face(const TriangleStore& m) {
  FloorFace face;
  face.space = [&m](VertexId v) { return Vec3{m.pos(v).x, m.pos(v).y, 0}; };
  face.to_space = [](Vec2 p) { return Vec3{p.x, p.y, 0}; };
  face.curve_point = [](VertexId, VertexId, double) { return std::optional<Vec2>{}; };
  face.curve_split_done = [](VertexId, VertexId, VertexId) {};
  face.is_corner = [](VertexId) { return false; };
  return face;
}

struct QfMeshed {
  ModelMesh mesh;
  Mesh2dResult r2;
  double min_rho = 1;
};

// Meshed at one size everywhere (no sizes from points, none extended from the boundary),
// as a coast is: the curves' nodes do not see how narrow the water between them is.
QfMeshed qf_mesh(const geo::Model& m, double floor, double size = 0.115) {
  QfMeshed out;
  Mesh1dOptions o1;
  o1.size.from_points = false;
  o1.size.extend_from_boundary = 0;
  o1.size.max = size;
  Mesh1dResult r1 = mesh_curves(m, o1);
  REQUIRE(r1.ok());
  out.mesh = std::move(r1.mesh);
  Mesh2dOptions o2;
  o2.size = o1.size;
  o2.quality_floor = floor;
  out.r2 = mesh_surfaces(m, out.mesh, o2);
  INFO(static_cast<int>(out.r2.error.problem));
  REQUIRE(out.r2.ok());
  for (const auto& [tag, sf] : out.mesh.surfaces)
    for (const auto& t : sf.triangles)
      out.min_rho =
          std::min(out.min_rho, rho(out.mesh.nodes[t[0]].xyz, out.mesh.nodes[t[1]].xyz, out.mesh.nodes[t[2]].xyz));
  return out;
}

// A unit square with an inlet 0.01 wide and 0.4 deep cut into its top, at size 0.115: the
// triangles at its end have edges ten times its width.
std::vector<Vec2> qf_inlet() {
  return {{0, 0}, {1, 0}, {1, 1}, {0.505, 1}, {0.505, 0.6}, {0.495, 0.6}, {0.495, 1}, {0, 1}};
}

// Every interior edge in exactly two triangles, every boundary edge in one, over all faces.
bool qf_conforming(const ModelMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& [tag, sf] : mesh.surfaces)
    for (const auto& t : sf.triangles)
      for (int e = 0; e < 3; ++e) ++uses[std::minmax(t[e], t[(e + 1) % 3])];
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> on_curve;
  for (const auto& [tag, cm] : mesh.curves)
    for (std::size_t k = 0; k + 1 < cm.nodes.size(); ++k) ++on_curve[std::minmax(cm.nodes[k], cm.nodes[k + 1])];
  for (const auto& [e, n] : uses) {
    const int expected = on_curve.count(e) ? (n == 2 ? 2 : 1) : 2;
    if (n != expected) return false;
    if (n == 1 && !on_curve.count(e)) return false;   // a boundary edge that no curve holds
  }
  return true;
}

}  // namespace

TEST_CASE("quality floor: the isoceles limit of 0.3 is about 9.5 degrees") {
  CHECK(sharp_angle_limit(0.3) * 180 / 3.14159265358979 == doctest::Approx(9.45).epsilon(0.01));
  CHECK(sharp_angle_limit(0) == 0);
}

TEST_CASE("quality floor: a face with a narrow inlet reaches rho >= 0.3") {
  geo::Model m;
  qf_add_polygon(m, qf_inlet(), 0.1);
  const QfMeshed off = qf_mesh(m, 0);
  MESSAGE("without the floor: rho min " << off.min_rho);
  REQUIRE(off.min_rho < 0.3);   // the test can fail: the inlet makes slivers
  const QfMeshed on = qf_mesh(m, 0.3);
  MESSAGE("with the floor: rho min " << on.min_rho << ", " << on.r2.stats.floor_curve_splits << " curve splits, "
                                     << on.r2.stats.floor_points << " points");
  CHECK(on.min_rho >= 0.3);
  CHECK(on.r2.notes.empty());
  CHECK(on.r2.stats.floor_curve_splits + on.r2.stats.floor_points > 0);
  // The inlet's sides gained nodes on their own lines: the geometry did not change.
  for (const auto& [tag, cm] : on.mesh.curves)
    for (std::uint32_t node : cm.nodes) {
      const Vec3 x = on.mesh.nodes[node].xyz;
      const geo::ModelCurve* mc = m.curve(tag);
      const Vec3 a = mc->shape->point(0), b = mc->shape->point(1);
      CHECK(norm(cross(b - a, x - a)) <= 1e-12 * norm(b - a));
    }
  CHECK(qf_conforming(on.mesh));
}

TEST_CASE("quality floor: a 5-degree corner is reported once, with its angle, and not looped on") {
  geo::Model m;
  const double a = 5 * 3.14159265358979 / 180;
  qf_add_polygon(m, {{0, 0}, {1, 0}, {std::cos(a), std::sin(a)}}, 0.1);
  const QfMeshed on = qf_mesh(m, 0.3);
  REQUIRE(on.r2.notes.size() == 1);
  const MeshNote& w = on.r2.notes[0];
  CHECK(w.kind == MeshNoteKind::FloorSharpCorners);
  CHECK(m.surface(w.surface) != nullptr);
  CHECK(w.floor == 0.3);
  CHECK(w.count >= 1);
  CHECK(w.sharp_limit_degrees > 9);
  CHECK(w.sharp_limit_degrees < 10);
  REQUIRE(w.corners.size() == 1);
  CHECK(w.corners[0].degrees == doctest::Approx(5));
  CHECK(w.corners[0].place.xyz == Vec3{0, 0, 0});
  CHECK(!w.corners[0].place.on_sphere);
  // Bounded: nothing is inserted for the corner's own triangle.
  CHECK(on.r2.stats.floor_curve_splits + on.r2.stats.floor_points < 300);
}

TEST_CASE("quality floor: a curve split for one face shows in the face beside it") {
  // Two squares side by side; the left one (meshed second) has a slot from their common
  // side x = 1, whose mouth is the right face's: splits of the common curves made for the
  // left face must reach the right one, meshed before it.
  geo::Model two;
  const double lc = 0.1;
  REQUIRE(two.add_point(1, {0, 0, 0}, lc).ok());
  REQUIRE(two.add_point(2, {1, 0, 0}, lc).ok());
  REQUIRE(two.add_point(3, {1, 1, 0}, lc).ok());
  REQUIRE(two.add_point(4, {0, 1, 0}, lc).ok());
  REQUIRE(two.add_point(5, {1, 0.505, 0}, lc).ok());
  REQUIRE(two.add_point(6, {0.6, 0.505, 0}, lc).ok());
  REQUIRE(two.add_point(7, {0.55, 0.495, 0}, lc).ok());
  REQUIRE(two.add_point(8, {1, 0.495, 0}, lc).ok());
  REQUIRE(two.add_point(9, {2, 0, 0}, lc).ok());
  REQUIRE(two.add_point(10, {2, 1, 0}, lc).ok());
  // Face 1 (meshed first): the right square, sharing x = 1 from y 0.51 to 1 (curve 3).
  REQUIRE(two.add_curve(1, geo::CurveKind::Line, {2, 9}).ok());
  REQUIRE(two.add_curve(2, geo::CurveKind::Line, {9, 10}).ok());
  REQUIRE(two.add_curve(3, geo::CurveKind::Line, {10, 3}).ok());
  REQUIRE(two.add_curve(4, geo::CurveKind::Line, {3, 5}).ok());
  REQUIRE(two.add_curve(5, geo::CurveKind::Line, {5, 8}).ok());
  REQUIRE(two.add_curve(6, geo::CurveKind::Line, {8, 2}).ok());
  REQUIRE(two.add_curve_loop(1, {1, 2, 3, 4, 5, 6}).ok());
  REQUIRE(two.add_plane_surface(1, {1}).ok());
  // Face 2: the left square with a slot 0.02 wide from x = 1 into it.
  REQUIRE(two.add_curve(7, geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(two.add_curve(8, geo::CurveKind::Line, {5, 6}).ok());
  REQUIRE(two.add_curve(9, geo::CurveKind::Line, {6, 7}).ok());
  REQUIRE(two.add_curve(10, geo::CurveKind::Line, {7, 8}).ok());
  REQUIRE(two.add_curve(11, geo::CurveKind::Line, {4, 1}).ok());
  REQUIRE(two.add_curve(12, geo::CurveKind::Line, {3, 4}).ok());
  REQUIRE(two.add_curve_loop(2, {7, -6, -10, -9, -8, -4, 12, 11}).ok());
  REQUIRE(two.add_plane_surface(2, {2}).ok());
  const QfMeshed both = qf_mesh(two, 0.3);
  MESSAGE("two faces: rho min " << both.min_rho << ", " << both.r2.stats.floor_curve_splits << " curve splits, "
                                  << both.r2.stats.floor_points << " points");
  CHECK(both.min_rho >= 0.3);
  CHECK(qf_conforming(both.mesh));
}

TEST_CASE("quality floor: a strip 0.01 wide under a face sharing its side never ends worse") {
  // The strip (face 2) shares its top with face 1, meshed before it: that curve is not
  // split (face 1's triangles on it would be cut unoptimised), the bottom alone cannot
  // mend the strip's slivers, and the first, loss-allowing run ends worse: the floor puts
  // everything back and its never-worse run changes nothing it cannot improve.
  geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}, 1).ok());
  REQUIRE(m.add_point(2, {1, 0, 0}, 1).ok());
  REQUIRE(m.add_point(3, {1, 0.01, 0}, 1).ok());
  REQUIRE(m.add_point(4, {0, 0.01, 0}, 1).ok());
  REQUIRE(m.add_point(5, {1, 1, 0}, 1).ok());
  REQUIRE(m.add_point(6, {0, 1, 0}, 1).ok());
  const std::vector<std::pair<int, int>> lines = {{1, 2}, {2, 3}, {3, 4}, {4, 1}, {3, 5}, {5, 6}, {6, 4}};
  for (std::size_t i = 0; i < lines.size(); ++i)
    REQUIRE(m.add_curve(static_cast<int>(i + 1), geo::CurveKind::Line, {lines[i].first, lines[i].second}).ok());
  REQUIRE(m.add_curve_loop(1, {-3, 5, 6, 7}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  REQUIRE(m.add_curve_loop(2, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(2, {2}).ok());
  const QfMeshed off = qf_mesh(m, 0);
  const QfMeshed on = qf_mesh(m, 0.3);
  MESSAGE("strip: rho min " << off.min_rho << " -> " << on.min_rho << ", " << on.r2.notes.size() << " warnings");
  REQUIRE(off.min_rho < 0.3);
  CHECK(on.min_rho >= off.min_rho);
  CHECK(on.mesh.curves.at(3).nodes == off.mesh.curves.at(3).nodes);   // the shared curve kept
  CHECK(qf_conforming(on.mesh));
  REQUIRE(on.r2.notes.size() == 1);
  CHECK(on.r2.notes[0].kind == MeshNoteKind::FloorStillBelow);
  CHECK(on.r2.notes[0].surface == 2);
  CHECK(on.r2.notes[0].floor == 0.3);
  CHECK(on.r2.notes[0].count > 0);
  CHECK(on.r2.notes[0].worst_rho < 0.3);
}

TEST_CASE("quality floor: a 13-degree corner with legs 1 : 2.6 gets the isoceles triangle of its angle") {
  // Above the sharp limit (9.5 degrees) but narrow: one triangle fills the wedge, and
  // halving its longer leg only moves the legs' ratio between 1 : 2 and 2 : 1 (rho 0.09
  // to 0.25) round after round towards the corner. The corner's short leg is a curve
  // shorter than the size (one edge, 0.045), the long one the x axis at size 0.115.
  geo::Model m;
  const double a = 13 * 3.14159265358979 / 180, leg = 0.045;
  qf_add_polygon(m, {{0, 0}, {1, 0}, {1, 0.5}, {leg * std::cos(a), leg * std::sin(a)}}, 0.1);
  const QfMeshed off = qf_mesh(m, 0);
  const QfMeshed on = qf_mesh(m, 0.3);
  MESSAGE("13-degree corner: rho min " << off.min_rho << " -> " << on.min_rho << ", "
                                       << on.r2.stats.floor_curve_splits << " curve splits");
  REQUIRE(off.min_rho < 0.3);
  CHECK(on.min_rho >= 0.3);
  CHECK(on.r2.notes.empty());
  CHECK(on.r2.stats.floor_curve_splits < 40);
  CHECK(qf_conforming(on.mesh));
}

TEST_CASE("quality floor: a short open side between two coasts that bend into the face") {
  // As where a box side cuts a coast 100 m wide (the Arctic at Vancouver Island): a side
  // 0.01 long at the bottom, and from its ends two B-spline coasts 1 long that bend
  // inwards. The triangle on the short side is a needle whose long side is a coast edge.
  // (The Arctic's needle also needed a flip before its cut, which this shape does not:
  // tests/scripts/examples/arctic_floor.geo is that case on the real coast.)
  geo::Model m;
  const double lc = 0.1;
  const std::vector<Vec2> left = {{0, 0}, {0.03, 0.3}, {0.05, 0.6}, {-0.2, 1}};
  const std::vector<Vec2> right = {{0.01, 0}, {0.06, 0.3}, {0.1, 0.6}, {0.6, 1}};
  int tag = 1;
  for (const Vec2& p : left) REQUIRE(m.add_point(tag++, {p.x, p.y, 0}, lc).ok());   // 1..4
  for (const Vec2& p : right) REQUIRE(m.add_point(tag++, {p.x, p.y, 0}, lc).ok());  // 5..8
  REQUIRE(m.add_curve(1, geo::CurveKind::Line, {1, 5}).ok());            // the short open side
  REQUIRE(m.add_curve(2, geo::CurveKind::BSpline, {5, 6, 7, 8}).ok());   // right coast, upwards
  REQUIRE(m.add_curve(3, geo::CurveKind::Line, {8, 4}).ok());            // the top
  REQUIRE(m.add_curve(4, geo::CurveKind::BSpline, {4, 3, 2, 1}).ok());   // left coast, downwards
  REQUIRE(m.add_curve_loop(1, {1, 2, 3, 4}).ok());
  REQUIRE(m.add_plane_surface(1, {1}).ok());
  const QfMeshed off = qf_mesh(m, 0);
  const QfMeshed on = qf_mesh(m, 0.3);
  MESSAGE("short open side: rho min " << off.min_rho << " -> " << on.min_rho << ", "
                                      << on.r2.stats.floor_curve_splits << " curve splits, "
                                      << on.r2.notes.size() << " warnings");
  REQUIRE(off.min_rho < 0.3);
  CHECK(on.min_rho >= 0.3);
  CHECK(on.r2.notes.empty());
  CHECK(qf_conforming(on.mesh));
  // The new coast nodes lie on the B-splines themselves.
  for (const int c : {2, 4}) {
    const geo::ModelCurve* mc = m.curve(c);
    for (std::size_t k = 0; k < on.mesh.curves.at(c).nodes.size(); ++k) {
      const Vec3 x = on.mesh.nodes[on.mesh.curves.at(c).nodes[k]].xyz;
      CHECK(norm(mc->shape->point(on.mesh.curves.at(c).t[k]) - x) <= 1e-12);
    }
  }
}

TEST_CASE("quality floor: every floor in [0, 0.9] ends with a conforming mesh or a located report") {
  // Floors above the default once crashed or never ended on the World Ocean. On the
  // narrow inlet every floor ends within its work budget: a conforming mesh, and whatever
  // is left below it reported with its place (tests/fuzz/fuzz_floor_entry.cpp tries
  // random coasts).
  geo::Model m;
  qf_add_polygon(m, qf_inlet(), 0.1);
  for (int qi = 0; qi <= 9; ++qi) {
    const double q = 0.1 * qi;
    const QfMeshed on = qf_mesh(m, q);
    INFO("floor " << q << ": rho min " << on.min_rho);
    CHECK(qf_conforming(on.mesh));
    if (on.min_rho < q - 1e-9) {
      bool reported = false;
      for (const MeshNote& w : on.r2.notes)
        reported = reported || (w.about_floor() && w.kind != MeshNoteKind::FloorFault);
      CHECK(reported);
    }
    for (const MeshNote& w : on.r2.notes) CHECK(w.kind != MeshNoteKind::FloorFault);
  }
}

TEST_CASE("quality floor: the work budget stops it and says so") {
  // The floor is bounded by a budget of operations, not only by rounds and
  // points. A strip of slivers between two rows of points (no curve to split): with a
  // budget of 10 operations it stops after 10, with the slivers still below the floor.
  TriangleStore m;
  std::vector<Vec2> xy;
  for (int i = 0; i <= 10; ++i) xy.push_back({0.1 * i, 0});
  for (int i = 0; i <= 10; ++i) xy.push_back({0.1 * i, 0.01});
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t i = 0; i < 10; ++i) {
    tris.push_back({i, i + 1, i + 12});
    tris.push_back({i, i + 12, i + 11});
  }
  REQUIRE(build_triangulation(xy, tris, m));
  FloorFace face = qf_flat_face(m);
  QualityFloorOptions opt;
  opt.floor = 0.3;
  opt.max_work = 10;
  const QualityFloorResult r = raise_quality_floor(m, face, opt);
  CHECK(r.below_before == 20);
  CHECK(r.work <= 10);
  CHECK(r.work_budget == 10);
  CHECK(r.out_of_work);
  CHECK(r.out_of_budget);
  CHECK(r.fault.empty());
  CHECK(r.below_after > 0);
}

TEST_CASE("quality floor: the same mesh on 1, 2 and 3 threads, never worse than without it (the scans in chunks)") {
  // The unit square at size 0.008 with an inlet 0.0008 wide and 0.1 deep: about 36,000
  // triangles, so each scan of the floor (the triangles below it, the corners, the points
  // in space) runs in several chunks. Refinement alone lifts it to about 0.7: a floor of
  // 0.8 (beyond refinement: the never-worse run) finds work.
  geo::Model m;
  qf_add_polygon(m, {{0, 0}, {1, 0}, {1, 1}, {0.5004, 1}, {0.5004, 0.9}, {0.4996, 0.9}, {0.4996, 1}, {0, 1}}, 0.1);
  std::vector<QfMeshed> runs;
  for (const auto& [floor, threads] : std::vector<std::pair<double, int>>{{0, 1}, {0.8, 1}, {0.8, 2}, {0.8, 3}}) {
    Mesh1dOptions o1;
    o1.size.from_points = false;
    o1.size.extend_from_boundary = 0;
    o1.size.max = 0.008;
    Mesh1dResult r1 = mesh_curves(m, o1);
    REQUIRE(r1.ok());
    QfMeshed out;
    out.mesh = std::move(r1.mesh);
    Mesh2dOptions o2;
    o2.size = o1.size;
    o2.quality_floor = floor;
    o2.threads = threads;
    out.r2 = mesh_surfaces(m, out.mesh, o2);
    REQUIRE(out.r2.ok());
    for (const auto& [tag, sf] : out.mesh.surfaces)
      for (const auto& t : sf.triangles)
        out.min_rho =
            std::min(out.min_rho, rho(out.mesh.nodes[t[0]].xyz, out.mesh.nodes[t[1]].xyz, out.mesh.nodes[t[2]].xyz));
    runs.push_back(std::move(out));
  }
  const auto& s1 = runs[1].mesh.surfaces.begin()->second;
  REQUIRE(s1.triangles.size() > 2 * 16384);   // three chunks at least
  MESSAGE("rho min " << runs[0].min_rho << " without the floor, " << runs[1].min_rho << " with it: "
                     << runs[1].r2.stats.floor_curve_splits << " curve splits, " << runs[1].r2.stats.floor_points
                     << " points");
  CHECK(runs[1].r2.stats.floor_curve_splits + runs[1].r2.stats.floor_points > 0);
  CHECK(runs[1].min_rho >= runs[0].min_rho);
  for (std::size_t i = 2; i < runs.size(); ++i) {
    const auto& si = runs[i].mesh.surfaces.begin()->second;
    CHECK(si.triangles == s1.triangles);
    REQUIRE(runs[i].mesh.nodes.size() == runs[1].mesh.nodes.size());
    bool same_nodes = true;
    for (std::size_t k = 0; k < runs[1].mesh.nodes.size(); ++k)
      same_nodes &= std::memcmp(&runs[i].mesh.nodes[k].xyz, &runs[1].mesh.nodes[k].xyz, sizeof(Vec3)) == 0;
    CHECK(same_nodes);
    // The floor's notes: the same kinds, counts, rounds and places.
    const auto& a = runs[i].r2.notes;
    const auto& b = runs[1].r2.notes;
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      CHECK(a[k].kind == b[k].kind);
      CHECK(a[k].count == b[k].count);
      CHECK(a[k].rounds == b[k].rounds);
      CHECK(a[k].new_points == b[k].new_points);
      CHECK(a[k].worst_rho == b[k].worst_rho);
      CHECK(std::memcmp(&a[k].place.xyz, &b[k].place.xyz, sizeof(Vec3)) == 0);
    }
  }
}

TEST_CASE("quality floor: count_below and worst_triangle give the serial answer on any thread count") {
  // A strip of 100,000 slivers and good triangles in a row: chunks of 16384 triangles.
  TriangleStore st;
  const std::uint32_t n = 100000;
  for (std::uint32_t i = 0; i <= n; ++i) {
    st.add_vertex({double(i), 0});
    st.add_vertex({double(i), (i % 7 == 3) ? 0.05 : 1.0});
  }
  for (std::uint32_t i = 0; i < n; ++i)
    st.add_triangle(VertexId{2 * i}, VertexId{2 * i + 2}, VertexId{2 * i + 1});
  const auto space = [&st](VertexId v) { return Vec3{st.pos(v).x, st.pos(v).y, 0}; };
  double w1 = 0;
  const std::uint32_t c1 = count_below(st, space, 0.3, &w1, 1);
  const auto [t1, r1] = worst_triangle(st, space, 1);
  CHECK(c1 > 0);
  CHECK(t1.valid());
  for (int threads : {2, 3, 5}) {
    double w = 0;
    CHECK(count_below(st, space, 0.3, &w, threads) == c1);
    CHECK(w == w1);
    const auto [t, r] = worst_triangle(st, space, threads);
    CHECK(t == t1);
    CHECK(r == r1);
  }
}

TEST_CASE("quality floor: with an undo journal its rounds measure only what changed, the same mesh as without") {
  // Rows of points 1 apart, every other gap 0.08 high: slivers in every second strip,
  // lifted by interior points over several rounds. With the store's undo journal attached
  // (as face_floor.cpp runs it), the rounds after the first measure only the slots below
  // the floor at the start, those the journal saw change and the new ones: the same list
  // as the scan of the whole store, so the same mesh and result.
  TriangleStore base;
  std::vector<Vec2> xy;
  const std::uint32_t nx = 40, ny = 40;
  for (std::uint32_t j = 0; j < ny; ++j)
    for (std::uint32_t i = 0; i < nx; ++i) xy.push_back({double(i) + 0.3 * (j % 3), (j / 2) * 1.08 + (j % 2) * 0.08});
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t j = 0; j + 1 < ny; ++j)
    for (std::uint32_t i = 0; i + 1 < nx; ++i) {
      const std::uint32_t a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      tris.push_back({a, b, d});
      tris.push_back({a, d, c});
    }
  REQUIRE(build_triangulation(xy, tris, base));
  const auto run = [](TriangleStore& m) {
    FloorFace face = qf_flat_face(m);
    QualityFloorOptions opt;
    opt.floor = 0.3;
    return raise_quality_floor(m, face, opt);
  };
  TriangleStore plain = base, journalled = base;
  double worst = 0;
  count_below(base, [&base](VertexId v) { return Vec3{base.pos(v).x, base.pos(v).y, 0}; }, 0.3, &worst);
  const QualityFloorResult rp = run(plain);
  CHECK(rp.worst_before == worst);   // the face's worst from the floor's own first scan
  StoreUndo undo(journalled);
  const QualityFloorResult rj = run(journalled);
  MESSAGE("rounds " << rp.rounds << ", points " << rp.interior_points << ", below " << rp.below_before << " -> "
                    << rp.below_after);
  CHECK(rp.rounds >= 2);
  CHECK(rp.interior_points > 0);
  CHECK(rj.rounds == rp.rounds);
  CHECK(rj.interior_points == rp.interior_points);
  CHECK(rj.below_after == rp.below_after);
  CHECK(rj.work == rp.work);
  CHECK(journalled.corner == plain.corner);
  CHECK(journalled.twin == plain.twin);
  REQUIRE(journalled.xy.size() == plain.xy.size());
  CHECK(std::memcmp(journalled.xy.data(), plain.xy.data(), plain.xy.size() * sizeof(Vec2)) == 0);
  undo.restore(journalled);
  CHECK(journalled.corner == base.corner);
}
