// The paper's section 3.2 repair loop: (1) Delaunay of all 1D points, (2)
// edge recovery by swaps, where swapping a constrained edge means the two
// 1D edges intersect, (3) split both at their parameter midpoint, snapped
// onto the curve, and go back to (1) until nothing crosses.
#include "mesh/boundary_recovery.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace sm {
namespace {

struct SegRef {
  std::uint32_t curve, seg;
  friend bool operator<(SegRef a, SegRef b) { return a.curve != b.curve ? a.curve < b.curve : a.seg < b.seg; }
  friend bool operator==(SegRef a, SegRef b) { return a.curve == b.curve && a.seg == b.seg; }
};

BoundaryError make_error(BoundaryErrorKind kind, std::uint32_t ca, std::uint32_t cb, Vec2 where,
                         std::uint32_t pa, std::uint32_t pb, std::string msg) {
  BoundaryError e;
  e.kind = kind;
  e.curve_a = ca, e.curve_b = cb;
  e.where = where;
  e.point_a = pa, e.point_b = pb;
  e.message = std::move(msg);
  return e;
}

}  // namespace

BoundaryResult recover_boundary(BoundaryProblem& problem, const SplitFn& split, const BoundaryOptions& opt) {
  BoundaryResult res;
  auto& pts = problem.points;
  auto& curves = problem.curves;
  for (std::uint32_t c = 0; c < curves.size(); ++c) {
    const auto& cv = curves[c];
    if (cv.pts.size() < 2 || cv.pts.size() != cv.t.size()) {
      res.error = make_error(BoundaryErrorKind::Invalid, cv.id, cv.id, {}, 0, 0,
                             fmt::format("curve {} needs at least two points with one parameter each", cv.id));
      res.error.fault = BoundaryFault::CurveTooFewPoints;
      return res;
    }
    for (std::uint32_t p : cv.pts)
      if (p >= pts.size()) {
        res.error = make_error(BoundaryErrorKind::Invalid, cv.id, cv.id, {}, p, p,
                               fmt::format("curve {} uses point {} of {}", cv.id, p, pts.size()));
        res.error.fault = BoundaryFault::PointOutOfRange;
        res.error.count = pts.size();
        return res;
      }
  }
  std::vector<SegRef> to_split;
  std::vector<SegRef> edge_ref;
  for (;;) {
    if (res.rounds++ >= opt.max_rounds) {
      res.error = make_error(BoundaryErrorKind::NoProgress, 0, 0, {}, 0, 0,
                             fmt::format("curve intersections still present after {} repair rounds", opt.max_rounds));
      res.error.fault = BoundaryFault::RoundsExhausted;
      res.error.count = opt.max_rounds;
      return res;
    }
    // (1) Delaunay of every point.
    TriangleStore& m = res.mesh;
    m.clear();
    m.xy = pts;
    const DelaunayResult dr = delaunay(m, opt.delaunay);
    // First curve using each point, to name curves in errors.
    std::vector<std::uint32_t> point_curve(pts.size(), kNoEdge);
    for (std::uint32_t c = 0; c < curves.size(); ++c)
      for (std::uint32_t p : curves[c].pts)
        if (point_curve[p] == kNoEdge) point_curve[p] = c;
    if (!dr.duplicates.empty()) {
      const auto d = dr.duplicates.front();
      const std::uint32_t ca = point_curve[d.kept.value], cb = point_curve[d.dup.value];
      const std::uint32_t ida = ca == kNoEdge ? 0 : curves[ca].id, idb = cb == kNoEdge ? 0 : curves[cb].id;
      res.error = make_error(BoundaryErrorKind::DuplicatePoint, ida, idb, pts[d.dup.value], d.kept.value, d.dup.value,
                             fmt::format("curves {} and {} have distinct points at the same place ({}, {})", ida, idb,
                                         pts[d.dup.value].x, pts[d.dup.value].y));
      return res;
    }
    if (!dr.ok()) {
      res.error =
          make_error(BoundaryErrorKind::Invalid, 0, 0, {}, 0, 0, "cannot triangulate the curve points: " + dr.error);
      res.error.fault = BoundaryFault::TriangulationFailed;
      res.error.reason = dr.error;
      return res;
    }
    // (2) Recover every curve edge.
    res.edges.clear();
    res.edge_curve.clear();
    edge_ref.clear();
    for (std::uint32_t c = 0; c < curves.size(); ++c)
      for (std::uint32_t k = 0; k + 1 < curves[c].pts.size(); ++k) {
        res.edges.push_back({VertexId{curves[c].pts[k]}, VertexId{curves[c].pts[k + 1]}});
        res.edge_curve.push_back(c);
        edge_ref.push_back({c, k});
      }
    const PlanarGeometry g{&m.xy};
    const RecoverResult rr = recover_edges(m, g, res.edges);
    if (!rr.ok()) {
      res.error = make_error(BoundaryErrorKind::Invalid, 0, 0, {}, 0, 0, "edge recovery failed: " + rr.error);
      res.error.fault = BoundaryFault::EdgeRecoveryFailed;
      res.error.reason = rr.error;
      return res;
    }
    if (rr.clean()) return res;
    // (3) Split every edge involved; stop when an intersecting edge is
    // already shorter than the tolerance: the curves really intersect.
    to_split.clear();
    auto edge_len = [&](std::uint32_t e) {
      return norm(pts[res.edges[e].second.value] - pts[res.edges[e].first.value]);
    };
    auto fail_if_short = [&](std::uint32_t e, std::uint32_t other_curve, Vec2 where) {
      if (edge_len(e) >= opt.tolerance) return false;
      const std::uint32_t ida = curves[res.edge_curve[e]].id, idb = curves[other_curve].id;
      res.error = make_error(
          BoundaryErrorKind::Intersection, ida, idb, where, res.edges[e].first.value, res.edges[e].second.value,
          ida == idb ? fmt::format("curve {} intersects itself near ({}, {})", ida, where.x, where.y)
                     : fmt::format("curves {} and {} intersect near ({}, {})", ida, idb, where.x, where.y));
      return true;
    };
    for (const EdgeCrossing& x : rr.crossings) {
      if (x.other == kNoEdge) continue;
      const Vec2 where = 0.5 * (pts[x.u.value] + pts[x.w.value]);
      if (fail_if_short(x.edge, res.edge_curve[x.other], where) ||
          fail_if_short(x.other, res.edge_curve[x.edge], where))
        return res;
      to_split.push_back(edge_ref[x.edge]);
      to_split.push_back(edge_ref[x.other]);
    }
    for (const VertexOnEdge& t : rr.touching) {
      const std::uint32_t pc = point_curve[t.v.value];
      const Vec2 where = pts[t.v.value];
      if (fail_if_short(t.edge, pc == kNoEdge ? res.edge_curve[t.edge] : pc, where)) return res;
      to_split.push_back(edge_ref[t.edge]);
    }
    std::sort(to_split.begin(), to_split.end());
    to_split.erase(std::unique(to_split.begin(), to_split.end()), to_split.end());
    // Highest segment first, so earlier segment numbers stay valid.
    for (std::size_t i = to_split.size(); i-- > 0;) {
      const auto [c, k] = to_split[i];
      BoundaryCurve& cv = curves[c];
      const double tm = 0.5 * (cv.t[k] + cv.t[k + 1]);
      const Vec2 p = split(c, tm);
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        res.error = make_error(BoundaryErrorKind::Invalid, cv.id, cv.id, pts[cv.pts[k]], cv.pts[k], cv.pts[k + 1],
                               fmt::format("curve {}: no point at parameter {}", cv.id, tm));
        res.error.fault = BoundaryFault::NoPointAtParameter;
        res.error.parameter = tm;
        return res;
      }
      pts.push_back(p);
      cv.pts.insert(cv.pts.begin() + k + 1, static_cast<std::uint32_t>(pts.size() - 1));
      cv.t.insert(cv.t.begin() + k + 1, tm);
      ++res.splits;
    }
  }
}

}  // namespace sm
