// Region clipping (Liang-Barsky per segment in lon/lat) and closing of the cut
// coastlines along the box, walking the box boundary counter-clockwise.
//
//   t = 3 ... 4 (left edge, north to south)      box perimeter parameter t in [0,4):
//   +------------------<------------------+      bottom edge W->E  t in [0,1)
//   |                  t=2..3 (top, E->W) |      right edge S->N   t in [1,2)
//   v                                     ^      top edge   E->W   t in [2,3)
//   |  t = 0 .. 1 (bottom, W->E)  t=1..2  |      left edge  N->S   t in [3,4)
//   +------------------>------------------+
#include "coast/region.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "coast/land_ring.h"
#include "coast/perimeter_link.h"
#include "coast/region_box.h"
#include "coast/region_loops.h"
#include "exact/ring.h"

namespace sm::coast {
namespace {

constexpr double kOnEdge = 1e-9;  // degrees: end points of GMT-cut polylines lie exactly on the box

Vec2 v2(geo::LonLat p) { return {p.lon, p.lat}; }

// A box spanning all longitudes is a polar cap (band mode): its only boundary is the
// parallel at `south`, run eastwards (the cap on the left), parameter t = lon/360 in [0,1).
bool is_band(const LonLatBox& b) { return b.east - b.west >= 360.0; }

double wrap360(double lon) {
  double l = std::fmod(lon, 360.0);
  return l < 0 ? l + 360.0 : l;
}

}  // namespace
namespace region_box {

bool strictly_outside(geo::LonLat p, const LonLatBox& b) {
  if (is_band(b)) return p.lat < b.south;
  return p.lon < b.west || p.lon > b.east || p.lat < b.south || p.lat > b.north;
}

bool on_boundary(geo::LonLat p, const LonLatBox& b) {
  if (is_band(b)) return std::abs(p.lat - b.south) < kOnEdge;
  const bool in = p.lon >= b.west - kOnEdge && p.lon <= b.east + kOnEdge && p.lat >= b.south - kOnEdge &&
                  p.lat <= b.north + kOnEdge;
  return in && (std::abs(p.lon - b.west) < kOnEdge || std::abs(p.lon - b.east) < kOnEdge ||
                std::abs(p.lat - b.south) < kOnEdge || std::abs(p.lat - b.north) < kOnEdge);
}

// Perimeter parameter of a point on the box boundary (nearest edge).
double box_param(geo::LonLat p, const LonLatBox& b) {
  if (is_band(b)) return wrap360(p.lon) / 360.0;
  const double w = b.east - b.west, h = b.north - b.south;
  const double d[4] = {std::abs(p.lat - b.south), std::abs(p.lon - b.east), std::abs(p.lat - b.north),
                       std::abs(p.lon - b.west)};
  const int e = static_cast<int>(std::min_element(d, d + 4) - d);
  double t = 0;
  switch (e) {
    case 0: t = (p.lon - b.west) / w; break;
    case 1: t = 1 + (p.lat - b.south) / h; break;
    case 2: t = 2 + (b.east - p.lon) / w; break;
    default: t = 3 + (b.north - p.lat) / h; break;
  }
  t = std::clamp(t, 0.0, 4.0);
  return t >= 4.0 ? 0.0 : t;
}

geo::LonLat box_point(double t, const LonLatBox& b) {
  const double w = b.east - b.west, h = b.north - b.south;
  t = std::fmod(t, 4.0);
  if (t < 1) return {b.west + t * w, b.south};
  if (t < 2) return {b.east, b.south + (t - 1) * h};
  if (t < 3) return {b.east - (t - 2) * w, b.north};
  return {b.west, b.north - (t - 3) * h};
}

// Box boundary from parameter ta counter-clockwise to tb (tb taken after ta), with
// corners and points at most `step` degrees apart, and on either side of each corner
// samples at step/2, step/4, ... down to corner_step degrees from it (their indices in
// `corners`, when given); end points exactly a and b. `closed`: a = b is a corner too
// (the whole box), graded on both sides but not listed (index 0 and the last point).
std::vector<geo::LonLat> box_path(geo::LonLat a, double ta, geo::LonLat b, double tb, const LonLatBox& box,
                                  double step, double corner_step, std::vector<std::size_t>* corners, bool closed) {
  if (is_band(box)) {   // eastwards along the parallel, keeping a's longitude contiguous
    double db = wrap360(b.lon - a.lon);
    if (db == 0) db = 360.0;
    const int m = std::max(1, static_cast<int>(std::ceil(db / step)));
    std::vector<geo::LonLat> out{a};
    for (int i = 1; i < m; ++i) out.push_back({a.lon + db * i / m, box.south});
    out.push_back(b);
    return out;
  }
  if (tb <= ta) tb += 4.0;
  std::vector<double> ts{ta};
  for (double c = std::floor(ta) + 1; c < tb; c += 1) ts.push_back(c);
  ts.push_back(tb);
  std::vector<geo::LonLat> out{a};
  std::vector<double> along;   // parameters of one edge's interior samples
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double t0 = ts[k], t1 = ts[k + 1];
    const int edge = static_cast<int>(std::floor(t0)) % 4;
    const double edge_deg = (edge % 2 == 0) ? box.east - box.west : box.north - box.south;
    const double len = (t1 - t0) * edge_deg;
    const int m = std::max(1, static_cast<int>(std::ceil(len / step)));
    along.clear();
    for (int i = 1; i < m; ++i) along.push_back(t0 + (t1 - t0) * i / m);
    // Graded samples next to the corners this edge starts (k > 0) or ends (k + 2 < size) at.
    if (corner_step > 0)
      for (double d = 0.5 * step; d >= corner_step && d < 0.5 * len; d *= 0.5) {
        if (k > 0 || closed) along.push_back(t0 + d / edge_deg);
        if (k + 2 < ts.size() || closed) along.push_back(t1 - d / edge_deg);
      }
    std::sort(along.begin(), along.end());
    along.erase(std::unique(along.begin(), along.end()), along.end());
    for (double t : along) out.push_back(box_point(t, box));
    if (k + 2 < ts.size()) {
      if (corners) corners->push_back(out.size());
      out.push_back(box_point(t1, box));
    }
  }
  out.push_back(b);
  return out;
}

// Liang-Barsky: the part [t0,t1] of p + t(q-p), t in [0,1], inside the closed box.
bool clip_segment(geo::LonLat p, geo::LonLat q, const LonLatBox& b, double& t0, double& t1) {
  t0 = 0, t1 = 1;
  const double dx = q.lon - p.lon, dy = q.lat - p.lat;
  const bool band = is_band(b);
  const double pk[4] = {band ? 0.0 : -dx, band ? 0.0 : dx, -dy, dy};
  const double qk[4] = {band ? 1.0 : p.lon - b.west, band ? 1.0 : b.east - p.lon, p.lat - b.south, b.north - p.lat};
  for (int k = 0; k < 4; ++k) {
    if (pk[k] == 0) {
      if (qk[k] < 0) return false;
      continue;
    }
    const double r = qk[k] / pk[k];
    if (pk[k] < 0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
  }
  return true;
}

geo::LonLat lerp(geo::LonLat p, geo::LonLat q, double t) {
  if (t == 0) return p;
  if (t == 1) return q;
  return {p.lon + t * (q.lon - p.lon), p.lat + t * (q.lat - p.lat)};
}

}  // namespace region_box
namespace {
using namespace region_box;

struct Chain {
  std::vector<geo::LonLat> pts;
  std::size_t ring;
};

}  // namespace

std::size_t orient_rings(std::vector<Ring>& rings) {
  std::size_t reversed = 0;
  std::vector<Vec2> xy;
  for (Ring& r : rings) {
    if (!r.closed) continue;
    bool flip = false;
    if (r.wraps_pole) {
      double mean_lat = 0;
      for (auto p : r.pts) mean_lat += p.lat;
      mean_lat /= static_cast<double>(r.pts.size());
      const double w = longitude_winding(r.pts);
      flip = mean_lat < 0 ? w > 0 : w < 0;   // pole on the left: westwards round the South Pole
    } else {
      xy.clear();
      for (auto p : r.pts) xy.push_back(v2(p));
      flip = ring_orientation(xy) == Sign::Negative;
    }
    if (flip) {
      std::reverse(r.pts.begin(), r.pts.end());
      ++reversed;
    }
  }
  return reversed;
}

Result<RegionResult> clip_to_region(const std::vector<Ring>& rings, const LonLatBox& box, const RegionOptions& opt) {
  if (!(box.west < box.east && box.south < box.north && box.south > -90 && box.north <= 90) ||
      (is_band(box) && box.north != 90))
    return CoastError{"region", -1,
                      fmt::format("invalid region {}/{}/{}/{}: need west < east, -90 < south < north <= 90, and a "
                                  "region spanning all longitudes must reach the North Pole (a polar cap)",
                                  box.west, box.east, box.south, box.north),
                      {}};
  const bool band = is_band(box);
  RegionResult out;
  std::vector<Chain> chains;
  std::vector<geo::LonLat> pts;
  for (std::size_t ri = 0; ri < rings.size(); ++ri) {
    const Ring& r = rings[ri];
    if (r.pts.empty()) continue;
    double lo = r.pts[0].lon, hi = lo;
    for (auto p : r.pts) lo = std::min(lo, p.lon), hi = std::max(hi, p.lon);
    for (int k = band ? 0 : -2; k <= (band ? 0 : 2); ++k) {
      const double shift = 360.0 * k;
      if (!band && (hi + shift < box.west || lo + shift > box.east)) continue;
      pts = r.pts;
      for (auto& p : pts) p.lon += shift;
      const std::size_t n = pts.size();
      std::size_t start = 0;
      std::size_t nseg = n - 1;
      if (r.closed) {
        std::size_t i0 = n;
        for (std::size_t i = 0; i < n && i0 == n; ++i)
          if (strictly_outside(pts[i], box)) i0 = i;
        if (i0 == n && !r.wraps_pole) {   // wholly inside the box: an island
          out.inside.push_back(ri);
          continue;
        }
        if (i0 == n) i0 = 0;
        start = i0;
        nseg = n;
      }
      std::optional<Chain> cur;
      auto close_chain = [&] {
        if (cur && cur->pts.size() >= 2) chains.push_back(std::move(*cur));
        cur.reset();
      };
      for (std::size_t s = 0; s < nseg; ++s) {
        const geo::LonLat p = pts[(start + s) % n], q = pts[(start + s + 1) % n];
        double t0, t1;
        if (!clip_segment(p, q, box, t0, t1)) {
          close_chain();
          continue;
        }
        const geo::LonLat a = lerp(p, q, t0), b = lerp(p, q, t1);
        if (!cur) {
          cur.emplace();
          cur->ring = ri;
          cur->pts.push_back(a);
        }
        if (!(cur->pts.back().lon == b.lon && cur->pts.back().lat == b.lat)) cur->pts.push_back(b);
        if (t1 < 1) close_chain();
      }
      close_chain();
    }
  }
  // Both ends of every chain must lie on the box to be closed along it.
  for (const Chain& c : chains)
    for (const geo::LonLat e : {c.pts.front(), c.pts.back()})
      if (!on_boundary(e, box))
        return CoastError{"region", static_cast<std::int64_t>(rings[c.ring].record),
                          "an open coastline ends inside the region: it cannot be closed along the box "
                          "(choose a region within the data's own box)",
                          e};
  if (chains.empty()) {
    // No coastline crosses the box: the box is all ocean (outer loop = the box) unless it
    // lies inside a land ring.
    const geo::LonLat mid{0.5 * (box.west + box.east), band ? 90.0 : 0.5 * (box.south + box.north)};
    if (const Ring* land = land_ring_holding(rings, mid))
      return CoastError{"region", static_cast<std::int64_t>(land->record), "the region lies wholly on land", mid};
    RegionLoop loop;
    RegionPiece piece;
    piece.open_boundary = true;
    const geo::LonLat c0 = band ? geo::LonLat{box.west, box.south} : box_point(0, box);
    piece.pts = box_path(c0, 0, c0, 4.0, box, opt.boundary_step_deg, opt.corner_step_deg, &piece.corners,
                         /*closed=*/!band);
    piece.pts.pop_back();   // closed on itself: the first point is not repeated
    if (!band) piece.corners.insert(piece.corners.begin(), 0);   // the start is the south-west corner
    loop.pieces.push_back(std::move(piece));
    out.loops.push_back(std::move(loop));
    return out;
  }
  // Going counter-clockwise from the start of a chain (an entry, land on its left), the
  // box runs through ocean up to the end of the next chain (perimeter_link.h, the chains
  // taken reversed: ocean on their left).
  std::vector<PerimeterChain> ends(chains.size());
  for (std::size_t c = 0; c < chains.size(); ++c)
    ends[c] = {box_param(chains[c].pts.back(), box), box_param(chains[c].pts.front(), box), false};
  const PerimeterLink link = link_along_perimeter(ends);
  if (link.error != PerimeterLinkError::None)
    return CoastError{"region", static_cast<std::int64_t>(rings[chains[link.bad_chain].ring].record),
                      "coastlines cut by the region are not consistently oriented (land on the left): "
                      "two coastlines enter the box in a row",
                      chains[link.bad_chain].pts.front()};
  const auto box_piece = [&](std::size_t c, std::size_t nc) {
    const geo::LonLat from = chains[c].pts.front(), to = chains[nc].pts.back();
    const double ta = box_param(from, box), tb = box_param(to, box);
    RegionPiece bnd;
    bnd.open_boundary = true;
    bnd.pts = box_path(from, ta, to, tb == ta ? ta + 4.0 : tb, box, opt.boundary_step_deg, opt.corner_step_deg,
                       &bnd.corners);
    if (band) {   // keep the piece's longitudes contiguous with the coast pieces it joins
      bnd.pts.back().lon =
          bnd.pts[bnd.pts.size() - 2].lon + wrap_delta(bnd.pts[bnd.pts.size() - 2].lon, bnd.pts.back().lon);
    }
    return bnd;
  };
  if (const std::optional<std::size_t> c0 = close_region_loops(chains, link.next, box_piece, out.loops))
    return CoastError{"region", static_cast<std::int64_t>(rings[chains[*c0].ring].record),
                      "coastlines cut by the region do not close into loops along the box", chains[*c0].pts.front()};
  return out;
}

}  // namespace sm::coast
