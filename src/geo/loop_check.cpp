// Curve-loop chaining and hole containment for plane surfaces.
#include "geo/loop_check.h"

#include "geo/model.h"
#include "exact/ring.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

namespace sm::geo {

GeoResult<std::vector<int>> chain_loop(int loop_tag, const std::vector<LoopEdge>& edges) {
  const std::size_t n = edges.size();
  // Edges by start vertex, in written order: the smallest unused index of a bucket is the
  // first remaining curve that Gmsh's linear scan would find.
  std::map<int, std::vector<std::size_t>> by_from;
  for (std::size_t i = 0; i < n; ++i) by_from[edges[i].from].push_back(i);
  std::map<int, std::size_t> bucket_pos;
  std::vector<bool> used(n, false);
  std::size_t next_unused = 0;
  std::vector<int> out;
  out.reserve(n);

  auto take = [&](std::size_t i) {
    used[i] = true;
    out.push_back(edges[i].curve);
  };
  auto next_from = [&](int v) -> std::size_t {
    auto it = by_from.find(v);
    if (it == by_from.end()) return n;
    std::size_t& pos = bucket_pos[v];
    while (pos < it->second.size() && used[it->second[pos]]) ++pos;
    return pos < it->second.size() ? it->second[pos] : n;
  };

  while (out.size() < n) {
    while (used[next_unused]) ++next_unused;
    const std::size_t first = next_unused;
    take(first);
    const int chain_start = edges[first].from;
    int end = edges[first].to;
    int last_curve = edges[first].curve;
    while (end != chain_start) {
      const std::size_t i = next_from(end);
      if (i == n) {
        // Name a remaining curve that ends here: it fits with the opposite sign.
        for (std::size_t k = 0; k < n; ++k)
          if (!used[k] && edges[k].to == end)
            return make_error(GeoErrorId::LoopCurveReversed, EntityKind::CurveLoop,
                              {loop_tag, edges[k].curve, last_curve}, {end});
        if (out.size() == n)
          return make_error(GeoErrorId::LoopDoesNotClose, EntityKind::CurveLoop, {loop_tag, last_curve},
                            {end, chain_start});
        return make_error(GeoErrorId::LoopBroken, EntityKind::CurveLoop, {loop_tag, last_curve}, {end});
      }
      take(i);
      end = edges[i].to;
      last_curve = edges[i].curve;
    }
  }
  return out;
}

GeoResult<std::vector<int>> chain_loop_reorienting(int loop_tag, const std::vector<LoopEdge>& edges) {
  const std::size_t n = edges.size();
  std::vector<bool> used(n, false);
  std::vector<int> out;
  out.reserve(n);
  // Each pass of the outer loop places one curve: at most n passes of n steps.
  int chain_start = 0, end = 0, last_curve = 0;
  while (out.size() < n) {
    if (out.empty() || end == chain_start) {   // a new chain: the first remaining curve as written
      const std::size_t first = static_cast<std::size_t>(std::find(used.begin(), used.end(), false) - used.begin());
      used[first] = true;
      out.push_back(edges[first].curve);
      chain_start = edges[first].from, end = edges[first].to, last_curve = edges[first].curve;
      continue;
    }
    std::size_t i = 0;
    while (i < n && (used[i] || (edges[i].from != end && edges[i].to != end))) ++i;
    if (i == n) return make_error(GeoErrorId::LoopBroken, EntityKind::CurveLoop, {loop_tag, last_curve}, {end});
    used[i] = true;
    const bool reversed = edges[i].from != end;
    last_curve = reversed ? -edges[i].curve : edges[i].curve;
    out.push_back(last_curve);
    end = reversed ? edges[i].from : edges[i].to;
  }
  if (end != chain_start)
    return make_error(GeoErrorId::LoopDoesNotClose, EntityKind::CurveLoop, {loop_tag, last_curve}, {end, chain_start});
  return out;
}

namespace {

int samples_for(const ModelCurve& c) {
  const int n = static_cast<int>(c.points.size());
  switch (c.kind) {
    case CurveKind::Line: return n - 1;   // exact: pieces are straight in the sampled plane
    case CurveKind::Spline:
    case CurveKind::BSpline: return std::max(8, 2 * n);
    default: return 32;
  }
}

}  // namespace

LoopPolygon sample_loop(const Model& m, const ModelCurveLoop& loop, const SurfaceGeometry* g) {
  LoopPolygon poly;
  for (int sc : loop.curves) {
    const ModelCurve& c = *m.curve(std::abs(sc));
    const Curve& shape = *c.shape;
    const int k = samples_for(c);
    const bool rev = sc < 0;
    // Each curve contributes its start and interior samples; the next curve adds its own start.
    for (int i = 0; i < k; ++i) {
      const double t = static_cast<double>(i) / k;
      if (g) {
        poly.uv.push_back(c.geometry ? shape.eval_uv(t, rev).p : g->param(shape.eval(t, rev).p));
      } else {
        poly.xyz.push_back(shape.eval(t, rev).p);
      }
    }
  }
  return poly;
}

LoopPolygon probe_loop(const Model& m, const ModelCurveLoop& loop, const SurfaceGeometry* g, int count) {
  LoopPolygon poly;
  const int n = static_cast<int>(loop.curves.size());
  for (int k = 0; k < count; ++k) {
    const double x = static_cast<double>(k) * n / count;   // position along the loop, in curves
    const int i = std::min(n - 1, static_cast<int>(x));
    const int sc = loop.curves[i];
    const ModelCurve& c = *m.curve(std::abs(sc));
    const Curve& shape = *c.shape;
    const double t = x - i;
    if (g) poly.uv.push_back(c.geometry ? shape.eval_uv(t, sc < 0).p : g->param(shape.eval(t, sc < 0).p));
    else poly.xyz.push_back(shape.eval(t, sc < 0).p);
  }
  return poly;
}

std::vector<Vec2> PlaneFrame::project(const std::vector<Vec3>& pts) const {
  std::vector<Vec2> out;
  out.reserve(pts.size());
  for (Vec3 p : pts) out.push_back({dot(p - origin, e1), dot(p - origin, e2)});
  return out;
}

PlaneFrame plane_frame(const std::vector<Vec3>& pts) {
  PlaneFrame f;
  if (pts.empty()) return f;
  Vec3 n{0, 0, 0};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec3 a = pts[i], b = pts[(i + 1) % pts.size()];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  f.origin = pts[0];
  if (norm(n) == 0) return f;
  n = n / norm(n);
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  f.e1 = cross(n, helper);
  f.e1 = f.e1 / norm(f.e1);
  f.e2 = cross(n, f.e1);
  return f;
}

PolygonIndex::PolygonIndex(std::vector<Vec2> polygon) : poly_(std::move(polygon)) {
  if (poly_.empty()) return;
  ylo_ = yhi_ = poly_[0].y;
  for (Vec2 p : poly_) {
    ylo_ = std::min(ylo_, p.y);
    yhi_ = std::max(yhi_, p.y);
  }
  const std::size_t m = poly_.size();
  bands_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(m))));
  h_ = (yhi_ - ylo_) / bands_;
  edges_.assign(bands_, {});
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2 a = poly_[i], b = poly_[(i + 1) % m];
    const int b0 = band_of(std::min(a.y, b.y)), b1 = band_of(std::max(a.y, b.y));
    for (int k = b0; k <= b1; ++k) edges_[k].push_back(i);
  }
}

int PolygonIndex::band_of(double y) const {
  if (!(h_ > 0)) return 0;
  return std::clamp(static_cast<int>((y - ylo_) / h_), 0, bands_ - 1);
}

bool PolygonIndex::contains(Vec2 p) const {
  const std::size_t m = poly_.size();
  if (m < 3 || p.y < ylo_ || p.y > yhi_) return false;
  bool in = false;
  for (std::size_t i : edges_[band_of(p.y)]) {
    const RayCrossing c = ray_crossing(poly_[i], poly_[(i + 1) % m], p);
    if (c == RayCrossing::OnEdge) return false;
    if (c == RayCrossing::Crosses) in = !in;
  }
  return in;
}

bool polygon_inside(const std::vector<Vec2>& inner, const PolygonIndex& outer) {
  if (inner.empty()) return false;
  const std::size_t tests = std::min<std::size_t>(16, inner.size());
  for (std::size_t k = 0; k < tests; ++k)
    if (!outer.contains(inner[k * inner.size() / tests])) return false;
  return true;
}

}  // namespace sm::geo
