// The paper's Figure 7 repair: chords of a coast and a nearby island cross
// although the curves do not; a genuinely crossing pair must fail, located.
#include <doctest/doctest.h>

#include <cmath>

#include "mesh/boundary_recovery.h"
#include "mesh/check.h"

using namespace sm;

namespace {

struct Circle {
  Vec2 c;
  double r, phase;
  Vec2 at(double t) const {
    const double a = phase + 2 * M_PI * t;
    return {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
};

// Appends a closed circle discretised with n points (parameters k/n, the
// last repeating the first point with t = 1).
void add_circle(BoundaryProblem& p, std::uint32_t id, const Circle& c, int n) {
  BoundaryCurve cv;
  cv.id = id;
  for (int k = 0; k < n; ++k) {
    cv.pts.push_back(static_cast<std::uint32_t>(p.points.size()));
    p.points.push_back(c.at(double(k) / n));
    cv.t.push_back(double(k) / n);
  }
  cv.pts.push_back(cv.pts.front());
  cv.t.push_back(1.0);
  p.curves.push_back(cv);
}

void check_result(const BoundaryResult& r, const BoundaryProblem& p, const std::vector<Circle>& circles) {
  INFO(r.error.message);
  REQUIRE(r.ok());
  INFO(check_topology(r.mesh).error);
  REQUIRE(check_topology(r.mesh).ok());
  REQUIRE(check_constraints(r.mesh, r.edges).ok());
  REQUIRE(check_delaunay(r.mesh, PlanarGeometry{&r.mesh.xy}, true).ok());
  // Every point, old and new, lies on its exact circle.
  for (std::size_t c = 0; c < p.curves.size(); ++c)
    for (std::uint32_t v : p.curves[c].pts)
      CHECK(std::fabs(norm(p.points[v] - circles[c].c) - circles[c].r) < 1e-12 * circles[c].r);
  // Parameters stay increasing and edges = sum of segments.
  std::size_t segs = 0;
  for (const auto& cv : p.curves) {
    segs += cv.pts.size() - 1;
    for (std::size_t k = 1; k < cv.t.size(); ++k) CHECK(cv.t[k] > cv.t[k - 1]);
  }
  CHECK(r.edges.size() == segs);
}

}  // namespace

TEST_CASE("boundary recovery: coast and an island almost touching (paper Fig. 7)") {
  // Coast: a circle of radius 10 with 12 points; its chord under the top
  // sags 0.34 below the arc. Island: radius 0.5, 0.05 below the arc.
  const std::vector<Circle> circles = {{{0, 0}, 10, M_PI / 2 + M_PI / 12}, {{0, 9.45}, 0.5, 0.1}};
  BoundaryProblem p;
  add_circle(p, 101, circles[0], 12);
  add_circle(p, 202, circles[1], 8);
  const auto split = [&](std::uint32_t c, double t) { return circles[c].at(t); };
  BoundaryOptions opt;
  opt.tolerance = 1e-6;
  const BoundaryResult r = recover_boundary(p, split, opt);
  check_result(r, p, circles);
  CHECK(r.rounds >= 2);  // the first 1D mesh did intersect
  CHECK(r.splits >= 2);
  CHECK(p.curves[0].pts.size() > 13);  // the coast chord was split
}

TEST_CASE("boundary recovery: several islands in a tight cluster near a coast") {
  std::vector<Circle> circles = {{{0, 0}, 10, 0.05}};
  for (int k = 0; k < 6; ++k) {
    const double a = 0.3 + 0.25 * k;
    circles.push_back({{9.3 * std::cos(a), 9.3 * std::sin(a)}, 0.6, 0.2 * k});
  }
  BoundaryProblem p;
  add_circle(p, 1, circles[0], 16);
  for (int k = 1; k <= 6; ++k) add_circle(p, 10 + k, circles[k], 6);
  const auto split = [&](std::uint32_t c, double t) { return circles[c].at(t); };
  const BoundaryResult r = recover_boundary(p, split, {});
  check_result(r, p, circles);
  CHECK(r.rounds >= 2);
}

TEST_CASE("boundary recovery: genuinely crossing curves fail with a located error") {
  const std::vector<Circle> circles = {{{0, 0}, 1, 0.1}, {{1.5, 0}, 1, 0.2}};
  BoundaryProblem p;
  add_circle(p, 7, circles[0], 10);
  add_circle(p, 9, circles[1], 10);
  const auto split = [&](std::uint32_t c, double t) { return circles[c].at(t); };
  BoundaryOptions opt;
  opt.tolerance = 1e-6;
  const BoundaryResult r = recover_boundary(p, split, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == BoundaryErrorKind::Intersection);
  const bool named = (r.error.curve_a == 7 && r.error.curve_b == 9) || (r.error.curve_a == 9 && r.error.curve_b == 7);
  CHECK(named);
  // The circles meet at (0.75, +-0.6614).
  const double dy = std::fabs(std::fabs(r.error.where.y) - std::sqrt(1 - 0.75 * 0.75));
  CHECK(std::fabs(r.error.where.x - 0.75) < 1e-5);
  CHECK(dy < 1e-5);
  CHECK(r.error.message.find("intersect") != std::string::npos);
}

TEST_CASE("boundary recovery: a curve crossing itself, duplicates, bad input") {
  // A figure-eight polyline through parameters of a lemniscate-like curve.
  const auto eight = [](double t) {
    const double a = 2 * M_PI * t;
    return Vec2{std::sin(a), std::sin(a) * std::cos(a)};
  };
  BoundaryProblem p;
  BoundaryCurve cv;
  cv.id = 5;
  for (int k = 0; k < 9; ++k) {
    cv.pts.push_back(k);
    p.points.push_back(eight((k + 0.25) / 9.0));
    cv.t.push_back((k + 0.25) / 9.0);
  }
  cv.pts.push_back(0);
  cv.t.push_back(1.0 + 0.25 / 9.0);  // back at point 0, one period later
  p.curves.push_back(cv);
  BoundaryOptions opt;
  opt.tolerance = 1e-7;
  const BoundaryResult r = recover_boundary(p, [&](std::uint32_t, double t) { return eight(t); }, opt);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == BoundaryErrorKind::Intersection);
  CHECK(r.error.curve_a == 5);
  CHECK(r.error.curve_b == 5);
  CHECK(norm(r.error.where) < 1e-5);  // the crossing is at the origin

  BoundaryProblem d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {1, 0}, {2, 1}};
  d.curves = {{3, {0, 1, 2}, {0, 0.5, 1}}, {4, {3, 4}, {0, 1}}};
  const BoundaryResult rd = recover_boundary(d, [](std::uint32_t, double) { return Vec2{}; });
  REQUIRE_FALSE(rd.ok());
  CHECK(rd.error.kind == BoundaryErrorKind::DuplicatePoint);
  CHECK(rd.error.message.find("curves 3 and 4") != std::string::npos);

  BoundaryProblem bad;
  bad.points = {{0, 0}};
  bad.curves = {{1, {0, 3}, {0, 1}}};
  CHECK(recover_boundary(bad, [](std::uint32_t, double) { return Vec2{}; }).error.kind == BoundaryErrorKind::Invalid);
}

TEST_CASE("boundary recovery: open curves sharing end points, split near the shared points") {
  // Two arcs of the circle of radius 10 share their end points (indices 0
  // and 1): the upper arc (curve 21) from angle 0 to pi, the lower (22) from
  // pi to 2 pi; each has 4 segments, so the chords sag well inside. An
  // island sits under the upper arc near its end point at angle 0.
  const auto arc = [](double a) { return Vec2{10 * std::cos(a), 10 * std::sin(a)}; };
  BoundaryProblem p;
  p.points = {arc(0), arc(M_PI)};
  BoundaryCurve up{21, {0}, {0.0}}, low{22, {1}, {M_PI}};
  for (int k = 1; k < 4; ++k) {
    up.pts.push_back(static_cast<std::uint32_t>(p.points.size()));
    up.t.push_back(k * M_PI / 4);
    p.points.push_back(arc(k * M_PI / 4));
    low.pts.push_back(static_cast<std::uint32_t>(p.points.size()));
    low.t.push_back(M_PI + k * M_PI / 4);
    p.points.push_back(arc(M_PI + k * M_PI / 4));
  }
  up.pts.push_back(1), up.t.push_back(M_PI);
  low.pts.push_back(0), low.t.push_back(2 * M_PI);
  p.curves = {up, low};
  const std::vector<Circle> circles = {{{0, 0}, 10, 0}, {{0, 0}, 10, 0}, {{8.9, 2.2}, 0.4, 0}};
  add_circle(p, 23, circles[2], 6);
  const auto split = [&](std::uint32_t c, double t) { return c < 2 ? arc(t) : circles[2].at(t); };
  const BoundaryResult r = recover_boundary(p, split, {});
  check_result(r, p, circles);
  CHECK(r.rounds >= 2);
  // The shared end points are still shared, once.
  CHECK(p.curves[0].pts.front() == 0);
  CHECK(p.curves[0].pts.back() == 1);
  CHECK(p.curves[1].pts.front() == 1);
  CHECK(p.curves[1].pts.back() == 0);
}
