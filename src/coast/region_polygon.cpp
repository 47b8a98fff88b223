// Polygon regions: the gnomonic frame, the polygon's checks, and the clipping of the
// shorelines with their closing along the polygon (perimeter parameter T = edge + fraction).
//
//   gnomonic plane tangent at the centre c:   x = (u.e1) / (u.c),  y = (u.e2) / (u.c)
//   (u the unit vector of a point; e1 east, e2 north at c). Great circles are lines, so a
//   great-circle edge is a segment and the lon/lat orientation is kept (e1, e2, c right-handed).
#include "coast/region_polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "coast/coastline_option_id.h"
#include "coast/land_ring.h"
#include "coast/perimeter_link.h"
#include "coast/region_loops.h"
#include "exact/ring.h"
#include "exact/segments.h"

namespace sm::coast {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
// Points farther than this from the centre are not projected: the polygon lies within
// kRegionPolygonMaxRadiusDeg, so a shoreline segment from there would be 25 degrees long.
const double kPolygonHorizonCos = std::cos(85.0 * kRadPerDeg);

Vec3 unit_of(geo::LonLat p) {
  const double lo = p.lon * kRadPerDeg, la = p.lat * kRadPerDeg;
  return {std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la)};
}

geo::LonLat lonlat_of(Vec3 u, double near_lon) {
  const double lat = std::atan2(u.z, std::hypot(u.x, u.y)) / kRadPerDeg;
  double lon = std::atan2(u.y, u.x) / kRadPerDeg;
  lon += 360.0 * std::round((near_lon - lon) / 360.0);
  return {lon, lat};
}

std::string where_text(geo::LonLat p) { return fmt::format("({:.6g}, {:.6g})", p.lon, p.lat); }

CoastError polygon_error(std::string message, std::optional<geo::LonLat> at = std::nullopt) {
  return CoastError{"region", -1, std::move(message), at, coast_option_string(CoastOpt::Region)};
}

// The side of the directed line a -> b a point x counts on: a point on the line counts as
// on the right. Both ends of a segment are tested with the same rule, so a point on an edge
// is outside, as point_in_ring has it.
bool left_of_line(Vec2 a, Vec2 b, Vec2 x) { return orient2d(a, b, x) == Sign::Positive; }

struct EdgeCrossing {
  double t;        // along the shoreline segment, 0..1
  double param;    // perimeter parameter: edge + fraction along it
  Vec2 at;         // on the edge, gnomonic
};

struct CutChain {
  std::vector<geo::LonLat> pts;
  std::size_t ring = 0;
  double t_in = -1, t_out = -1;   // perimeter parameters of its two ends (-1: not on the polygon)
};

}  // namespace

bool RegionPolygon::project(geo::LonLat p, Vec2& out) const {
  const Vec3 u = unit_of(p);
  const double d = dot(u, c_);
  if (!(d > kPolygonHorizonCos)) return false;
  out = {dot(u, e1_) / d, dot(u, e2_) / d};
  return true;
}

geo::LonLat RegionPolygon::unproject(Vec2 xy, double near_lon) const {
  const Vec3 v = c_ + xy.x * e1_ + xy.y * e2_;
  return lonlat_of(v / norm(v), near_lon);
}

double RegionPolygon::arc_deg(geo::LonLat a, geo::LonLat b) {
  const Vec3 ua = unit_of(a), ub = unit_of(b);
  return std::atan2(norm(cross(ua, ub)), dot(ua, ub)) / kRadPerDeg;
}

geo::LonLat RegionPolygon::along_arc(geo::LonLat a, geo::LonLat b, double f) {
  if (f <= 0) return a;
  if (f >= 1) return b;
  const Vec3 ua = unit_of(a), ub = unit_of(b);
  const double w = std::atan2(norm(cross(ua, ub)), dot(ua, ub));
  if (w < 1e-15) return a;
  const Vec3 v = (std::sin((1 - f) * w) * ua + std::sin(f * w) * ub) / std::sin(w);
  return lonlat_of(v / norm(v), a.lon);
}

Result<RegionPolygon> RegionPolygon::make(const std::vector<geo::LonLat>& given) {
  const std::size_t n = given.size();
  if (n < 3) return polygon_error(fmt::format("a region polygon needs at least 3 vertices, not {}", n));
  if (n > kRegionPolygonMaxVertices)
    return polygon_error(fmt::format("a region polygon may have at most {} vertices, not {}",
                                    kRegionPolygonMaxVertices, n));
  Vec3 sum{};
  for (std::size_t i = 0; i < n; ++i) {
    const geo::LonLat p = given[i];
    if (!std::isfinite(p.lon) || !std::isfinite(p.lat) || p.lat < -90 || p.lat > 90)
      return polygon_error(
          fmt::format("region polygon vertex {} {}: the latitude must lie in [-90, 90]", i + 1, where_text(p)), p);
    const geo::LonLat q = given[(i + 1) % n];
    if (arc_deg(p, q) < 1e-9)
      return polygon_error(
          fmt::format("region polygon vertices {} and {} are the same point {}", i + 1, (i + 1) % n + 1, where_text(p)),
          p);
    sum += unit_of(p);
  }
  RegionPolygon poly;
  if (norm(sum) < 1e-9)
    return polygon_error("the region polygon's vertices have no centre (they spread round the sphere)");
  poly.c_ = sum / norm(sum);
  Vec3 east = cross(Vec3{0, 0, 1}, poly.c_);
  if (norm(east) < 1e-9) east = {0, 1, 0};   // centre at a pole: any east will do
  poly.e1_ = east / norm(east);
  poly.e2_ = cross(poly.c_, poly.e1_);
  const double max_cos = std::cos(kRegionPolygonMaxRadiusDeg * kRadPerDeg);
  for (std::size_t i = 0; i < n; ++i) {
    if (dot(unit_of(given[i]), poly.c_) < max_cos)
      return polygon_error(fmt::format("region polygon vertex {} {} lies more than {} degrees from the polygon's "
                                      "centre: split the region, or use a box",
                                      i + 1, where_text(given[i]), kRegionPolygonMaxRadiusDeg),
                          given[i]);
    Vec2 xy;
    poly.project(given[i], xy);
    poly.gn_.push_back(xy);
    poly.ll_.push_back(given[i]);
  }
  // Simple: non-neighbouring edges share no point, neighbours only their vertex.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2 a = poly.gn_[i], b = poly.gn_[(i + 1) % n], c = poly.gn_[j], d = poly.gn_[(j + 1) % n];
      const SegmentContact k = segment_contact(a, b, c, d);
      const bool neighbours = j == i + 1 || (i == 0 && j == n - 1);
      const bool bad = neighbours ? k.kind == SegmentContactKind::Overlap : k.kind != SegmentContactKind::None;
      if (bad)
        return polygon_error(
            fmt::format("the region polygon crosses itself: edges {} and {} meet (vertex {} {} to "
                        "vertex {}, and vertex {} to vertex {})",
                        i + 1, j + 1, i + 1, where_text(given[i]), (i + 1) % n + 1, j + 1, (j + 1) % n + 1),
            given[i]);
    }
  const Sign o = ring_orientation(poly.gn_);
  if (o == Sign::Zero) return polygon_error("the region polygon has no area");
  if (o == Sign::Negative) {
    std::reverse(poly.gn_.begin(), poly.gn_.end());
    std::reverse(poly.ll_.begin(), poly.ll_.end());
    poly.reversed_ = true;
  }
  poly.lo_ = poly.hi_ = poly.gn_[0];
  for (Vec2 v : poly.gn_) {
    poly.lo_ = {std::min(poly.lo_.x, v.x), std::min(poly.lo_.y, v.y)};
    poly.hi_ = {std::max(poly.hi_.x, v.x), std::max(poly.hi_.y, v.y)};
  }
  for (const geo::LonLat pole : {geo::LonLat{0, 90}, geo::LonLat{0, -90}})
    if (poly.contains(pole))
      return polygon_error(
          fmt::format("the region polygon holds the {} Pole: use a box reaching the pole (a polar cap)",
                      pole.lat > 0 ? "North" : "South"));
  return poly;
}

bool RegionPolygon::contains(geo::LonLat p) const {
  Vec2 xy;
  if (!project(p, xy)) return false;
  if (xy.x < lo_.x || xy.x > hi_.x || xy.y < lo_.y || xy.y > hi_.y) return false;
  return point_in_ring(gn_, xy);
}

LonLatBox RegionPolygon::bounding_box() const {
  // Edges bulge towards the poles between their vertices: 64 samples an edge bound the
  // bulge within a small margin, and 0.01 degree more keeps the reader's bins inclusive.
  constexpr int kSamples = 64;
  constexpr double kMargin = 0.01;
  double west = ll_[0].lon, east = west, south = ll_[0].lat, north = south;
  double lon = ll_[0].lon;
  for (std::size_t i = 0; i < size(); ++i) {
    const geo::LonLat a = ll_[i], b = ll_[(i + 1) % size()];
    for (int s = 0; s <= kSamples; ++s) {
      geo::LonLat p = along_arc(a, b, static_cast<double>(s) / kSamples);
      p.lon = lon + wrap_delta(lon, p.lon);   // contiguous with the walk so far
      lon = p.lon;
      west = std::min(west, p.lon), east = std::max(east, p.lon);
      south = std::min(south, p.lat), north = std::max(north, p.lat);
    }
  }
  return {west - kMargin, east + kMargin, std::max(-90.0, south - kMargin), std::min(90.0, north + kMargin)};
}

std::vector<std::size_t> RegionPolygon::edges_along(const std::vector<geo::LonLat>& pts) const {
  constexpr double kOn = 1e-9;   // radians off the edge's great circle
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < size(); ++i) {
    const Vec3 a = unit_of(ll_[i]), b = unit_of(ll_[(i + 1) % size()]);
    Vec3 nrm = cross(a, b);
    nrm = nrm / norm(nrm);
    auto on = [&](geo::LonLat p) {
      const Vec3 u = unit_of(p);
      // On the great circle, and between a and b (on the same side of both ends' planes).
      return std::abs(dot(u, nrm)) < kOn && dot(cross(a, u), nrm) >= -kOn && dot(cross(u, b), nrm) >= -kOn;
    };
    for (std::size_t k = 0; k + 1 < pts.size(); ++k)
      if (on(pts[k]) && on(pts[k + 1])) {
        out.push_back(given_edge(i));
        break;
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

// The polygon's boundary from parameter ta counter-clockwise to tb (tb taken after ta),
// with the vertices, points at most `step` degrees of arc apart, and graded samples at
// step/2, step/4, ... down to corner_step from each vertex passed (their indices in
// `corners`); end points exactly a and b. `closed`: the whole polygon from vertex 0.
std::vector<geo::LonLat> polygon_path(const RegionPolygon& poly, geo::LonLat a, double ta, geo::LonLat b, double tb,
                                      double step, double corner_step, std::vector<std::size_t>* corners,
                                      bool closed = false) {
  const double n = static_cast<double>(poly.size());
  if (tb <= ta) tb += n;
  std::vector<double> ts{ta};
  for (double c = std::floor(ta) + 1; c < tb; c += 1) ts.push_back(c);
  ts.push_back(tb);
  auto vertex_at = [&](double t) {   // t a whole number
    return poly.vertex(static_cast<std::size_t>(t) % poly.size());
  };
  std::vector<geo::LonLat> out{a};
  std::vector<double> fracs;   // arc fractions of one sub-edge's interior samples
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const geo::LonLat p0 = k == 0 ? a : out.back();
    const geo::LonLat p1 = k + 2 == ts.size() ? b : vertex_at(ts[k + 1]);
    const double len = RegionPolygon::arc_deg(p0, p1);
    const int m = std::max(1, static_cast<int>(std::ceil(len / step)));
    fracs.clear();
    for (int i = 1; i < m; ++i) fracs.push_back(static_cast<double>(i) / m);
    if (corner_step > 0 && len > 0)
      for (double d = 0.5 * step; d >= corner_step && d < 0.5 * len; d *= 0.5) {
        if (k > 0 || closed) fracs.push_back(d / len);
        if (k + 2 < ts.size() || closed) fracs.push_back(1 - d / len);
      }
    std::sort(fracs.begin(), fracs.end());
    fracs.erase(std::unique(fracs.begin(), fracs.end()), fracs.end());
    for (double f : fracs) out.push_back(RegionPolygon::along_arc(p0, p1, f));
    if (k + 2 < ts.size()) {
      if (corners) corners->push_back(out.size());
      geo::LonLat v = p1;
      v.lon = out.back().lon + wrap_delta(out.back().lon, v.lon);
      out.push_back(v);
    }
  }
  geo::LonLat last = b;
  last.lon = out.back().lon + wrap_delta(out.back().lon, last.lon);   // contiguous within the piece
  out.push_back(last);
  return out;
}

// Where the shoreline segment p -> q (gnomonic) crosses the polygon's edges, by t along it.
void crossings_of(const RegionPolygon& poly, Vec2 p, Vec2 q, std::vector<EdgeCrossing>& out) {
  out.clear();
  const std::size_t n = poly.size();
  const Vec2 lo{std::min(p.x, q.x), std::min(p.y, q.y)}, hi{std::max(p.x, q.x), std::max(p.y, q.y)};
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2 a = poly.plane(e), b = poly.plane((e + 1) % n);
    if (std::max(a.x, b.x) < lo.x || std::min(a.x, b.x) > hi.x || std::max(a.y, b.y) < lo.y ||
        std::min(a.y, b.y) > hi.y)
      continue;
    if (left_of_line(a, b, p) == left_of_line(a, b, q)) continue;
    if (left_of_line(p, q, a) == left_of_line(p, q, b)) continue;
    const Vec2 d = q - p, f = b - a;
    const double den = cross(d, f);
    double t = den != 0 ? cross(a - p, f) / den : 0.5;
    double s = den != 0 ? cross(a - p, d) / den : 0.5;
    t = std::clamp(t, 0.0, 1.0);
    s = std::clamp(s, 0.0, 1.0);
    if (s >= 1.0) s = std::nextafter(1.0, 0.0);   // the parameter stays on edge e
    out.push_back({t, static_cast<double>(e) + s, a + s * f});
  }
  std::sort(out.begin(), out.end(),
            [](const EdgeCrossing& x, const EdgeCrossing& y) { return x.t != y.t ? x.t < y.t : x.param < y.param; });
}

// Walks ring `ri` along the polygon's edges, appending the pieces of it that lie inside
// (each with the perimeter parameters where it enters and leaves) to `chains`; a closed
// ring wholly inside goes to out.inside. The walk starts from point 0, whose side is
// known, and toggles at each crossing.
std::optional<CoastError> cut_ring(const RegionPolygon& poly, const Ring& r, std::size_t ri,
                                   std::vector<CutChain>& chains, RegionResult& out) {
  const std::size_t n = r.pts.size();
  std::vector<Vec2> xy(n);
  std::vector<char> near(n, 0);   // projected (within 85 degrees of the centre)
  bool any_near = false;
  for (std::size_t i = 0; i < n; ++i) any_near |= (near[i] = poly.project(r.pts[i], xy[i]) ? 1 : 0) != 0;
  if (!any_near) return std::nullopt;
  const std::size_t nseg = r.closed ? n : n - 1;
  bool inside = poly.contains(r.pts[0]);
  const bool start_inside = inside;
  const std::size_t first_chain = chains.size();
  bool crossed = false;
  std::optional<CutChain> cur;
  if (inside) {
    cur.emplace();
    cur->ring = ri;
    cur->pts.push_back(r.pts[0]);
  }
  std::vector<EdgeCrossing> cx;
  for (std::size_t s = 0; s < nseg; ++s) {
    const std::size_t i = s, j = (s + 1) % n;
    if (!near[i] || !near[j]) {
      if (inside || (near[i] && poly.contains(r.pts[i])) || (near[j] && poly.contains(r.pts[j])))
        return CoastError{"region", static_cast<std::int64_t>(r.record),
                          "a shoreline segment reaches into the region polygon from more than 85 degrees away",
                          r.pts[near[i] ? i : j]};
      continue;
    }
    crossings_of(poly, xy[i], xy[j], cx);
    for (const EdgeCrossing& c : cx) {
      crossed = true;
      const geo::LonLat at = poly.unproject(c.at, r.pts[i].lon);
      if (!inside) {
        cur.emplace();
        cur->ring = ri;
        cur->t_in = c.param;
        cur->pts.push_back(at);
      } else {
        if (!(cur->pts.back().lon == at.lon && cur->pts.back().lat == at.lat)) cur->pts.push_back(at);
        cur->t_out = c.param;
        chains.push_back(std::move(*cur));
        cur.reset();
      }
      inside = !inside;
    }
    if (inside && (r.closed ? j != 0 : true)) cur->pts.push_back(r.pts[j]);
  }
  if (r.closed && inside != start_inside)
    return CoastError{"region", static_cast<std::int64_t>(r.record),
                      "a shoreline crosses the region polygon an odd number of times (it touches a vertex of the "
                      "polygon exactly: move that vertex a little)",
                      r.pts[0]};
  if (!crossed) {
    if (r.closed && start_inside) out.inside.push_back(ri);
    if (r.closed || !start_inside) return std::nullopt;
  }
  if (cur) {   // still inside at the end
    if (r.closed && start_inside && first_chain < chains.size()) {
      // The walk began inside at point 0, which this chain stopped short of: the chain
      // the walk began with continues this one.
      CutChain& head = chains[first_chain];
      cur->pts.insert(cur->pts.end(), head.pts.begin(), head.pts.end());
      cur->t_out = head.t_out;
      head = std::move(*cur);
    } else {
      chains.push_back(std::move(*cur));
    }
  }
  return std::nullopt;
}

// No coastline crosses the polygon: the whole polygon is one loop of open boundary,
// unless it lies inside a land ring. A point inside: the lowest vertex is convex, and a
// point just inside its corner is inside the polygon once no other vertex comes closer
// than the step.
Result<RegionResult> polygon_all_ocean(const std::vector<Ring>& rings, const RegionPolygon& poly,
                                       const RegionOptions& opt) {
  std::size_t low = 0;
  for (std::size_t i = 1; i < poly.size(); ++i)
    if (poly.plane(i).y < poly.plane(low).y) low = i;
  const Vec2 v = poly.plane(low), a = poly.plane((low + poly.size() - 1) % poly.size()),
             b = poly.plane((low + 1) % poly.size());
  std::optional<geo::LonLat> mid;
  double f = 0.25;
  for (int k = 0; k < 60 && !mid; ++k, f *= 0.5) {
    const Vec2 m = v + f * (0.5 * (a - v) + 0.5 * (b - v));
    const geo::LonLat ll = poly.unproject(m, poly.vertex(low).lon);
    if (poly.contains(ll)) mid = ll;
  }
  if (!mid) return polygon_error("the region polygon has no point inside it");
  if (const Ring* land = land_ring_holding(rings, *mid))
    return CoastError{"region", static_cast<std::int64_t>(land->record), "the region polygon lies wholly on land", *mid,
                      coast_option_string(CoastOpt::Region)};
  RegionResult out;
  RegionLoop loop;
  RegionPiece piece;
  piece.open_boundary = true;
  const geo::LonLat v0 = poly.vertex(0);
  piece.pts = polygon_path(poly, v0, 0, v0, static_cast<double>(poly.size()), opt.boundary_step_deg,
                           opt.corner_step_deg, &piece.corners, /*closed=*/true);
  piece.pts.pop_back();   // closed on itself: the first point is not repeated
  piece.corners.insert(piece.corners.begin(), 0);
  loop.pieces.push_back(std::move(piece));
  out.loops.push_back(std::move(loop));
  return out;
}

// The chains closed into loops along the perimeter, as clip_to_region does along the box
// (perimeter_link.h): from a chain's start the polygon runs through ocean to the end of
// the next chain.
std::optional<CoastError> link_chains(const std::vector<Ring>& rings, const RegionPolygon& poly,
                                      const RegionOptions& opt, const std::vector<CutChain>& chains,
                                      RegionResult& out) {
  std::vector<PerimeterChain> ends(chains.size());
  for (std::size_t c = 0; c < chains.size(); ++c) ends[c] = {chains[c].t_out, chains[c].t_in, false};
  const PerimeterLink link = link_along_perimeter(ends);
  if (link.error != PerimeterLinkError::None)
    return CoastError{"region", static_cast<std::int64_t>(rings[chains[link.bad_chain].ring].record),
                      "coastlines cut by the region polygon are not consistently oriented (land on the left): "
                      "two coastlines enter it in a row",
                      chains[link.bad_chain].pts.front()};
  const auto polygon_piece = [&](std::size_t c, std::size_t nc) {
    const double ta = chains[c].t_in, tb = chains[nc].t_out;
    RegionPiece bnd;
    bnd.open_boundary = true;
    bnd.pts = polygon_path(poly, chains[c].pts.front(), ta, chains[nc].pts.back(),
                           tb == ta ? ta + static_cast<double>(poly.size()) : tb, opt.boundary_step_deg,
                           opt.corner_step_deg, &bnd.corners);
    return bnd;
  };
  if (const std::optional<std::size_t> c0 = close_region_loops(chains, link.next, polygon_piece, out.loops))
    return CoastError{"region", static_cast<std::int64_t>(rings[chains[*c0].ring].record),
                      "coastlines cut by the region polygon do not close into loops along it", chains[*c0].pts.front()};
  return std::nullopt;
}

}  // namespace

Result<RegionResult> clip_to_polygon(const std::vector<Ring>& rings, const RegionPolygon& poly,
                                     const RegionOptions& opt) {
  RegionResult out;
  std::vector<CutChain> chains;
  for (std::size_t ri = 0; ri < rings.size(); ++ri)
    if (rings[ri].pts.size() >= 2)
      if (std::optional<CoastError> e = cut_ring(poly, rings[ri], ri, chains, out)) return std::move(*e);
  for (const CutChain& c : chains)
    if (c.t_in < 0 || c.t_out < 0)
      return CoastError{"region", static_cast<std::int64_t>(rings[c.ring].record),
                        "an open coastline ends inside the region polygon: it cannot be closed along the polygon "
                        "(choose a region within the data's own box)",
                        c.t_in < 0 ? c.pts.front() : c.pts.back()};
  if (chains.empty()) {
    Result<RegionResult> all = polygon_all_ocean(rings, poly, opt);
    if (all.ok()) all.value().inside = std::move(out.inside);
    return all;
  }
  if (std::optional<CoastError> e = link_chains(rings, poly, opt, chains, out)) return std::move(*e);
  return out;
}

}  // namespace sm::coast
