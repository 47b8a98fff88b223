// See patch.h. Chains are cut at the box with region.cpp's Liang-Barsky clip (region_box.h);
// every chain is used once in the walk that joins them into rings, so the walk is bounded
// by the number of chains.
#include "coast/patch.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "coast/coastline_option_id.h"
#include "coast/perimeter_link.h"
#include "coast/region_box.h"
#include "exact/ring.h"

namespace sm::coast {
namespace {

using namespace region_box;

struct PatchChain {
  std::vector<geo::LonLat> pts;
  std::size_t ring = 0;
  bool outside = false;
  double t_first = -1, t_last = -1;
};

bool is_water(int level) { return level == 2 || level == 4; }

bool strictly_inside(geo::LonLat p, const LonLatBox& b) {
  return p.lon > b.west && p.lon < b.east && p.lat > b.south && p.lat < b.north;
}

bool same(geo::LonLat a, geo::LonLat b) { return a.lon == b.lon && a.lat == b.lat; }

// Length in metres of a lon/lat polyline (each step a chord of the sphere: the box steps
// are short).
double length_m(const std::vector<geo::LonLat>& pts, double radius) {
  constexpr double k = std::numbers::pi / 180.0;
  double s = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double c = std::cos(0.5 * (pts[i].lat + pts[i + 1].lat) * k);
    s += std::hypot((pts[i + 1].lon - pts[i].lon) * c, pts[i + 1].lat - pts[i].lat) * k * radius;
  }
  return s;
}

// The parts of ring r inside (keep_inside) or outside the box as chains; false when no
// segment reaches the box (the ring lies wholly on one side).
bool cut_ring(const Ring& r, std::size_t ri, const LonLatBox& box, bool keep_inside, std::vector<PatchChain>& out) {
  const std::size_t n = r.pts.size();
  if (n < 2) return false;
  std::size_t start = 0, nseg = n - 1;
  if (r.closed) {
    std::size_t i0 = n;
    for (std::size_t i = 0; i < n && i0 == n; ++i)
      if (strictly_outside(r.pts[i], box)) i0 = i;
    if (i0 == n) return false;   // wholly inside
    start = i0;
    nseg = n;
  }
  const std::size_t first = out.size();
  bool touched = false;
  std::optional<PatchChain> cur;
  auto add = [&](geo::LonLat x, double t_first) {
    if (!cur) {
      cur.emplace();
      cur->ring = ri;
      cur->outside = !keep_inside;
      cur->t_first = t_first;
      cur->pts.push_back(x);
    } else if (!same(cur->pts.back(), x)) {
      cur->pts.push_back(x);
    }
  };
  auto end_at = [&](geo::LonLat x, double t_last) {
    if (!cur) return;
    if (!same(cur->pts.back(), x)) cur->pts.push_back(x);
    cur->t_last = t_last;
    if (cur->pts.size() >= 2) out.push_back(std::move(*cur));
    cur.reset();
  };
  for (std::size_t s = 0; s < nseg; ++s) {
    const geo::LonLat p = r.pts[(start + s) % n], q = r.pts[(start + s + 1) % n];
    double t0, t1;
    // A segment meets the box when part of it lies strictly inside: one touching the box
    // at a point, or running along an edge, does not (no zero-length or zero-area chain).
    // Vertices exactly on an edge (OSM and GSHHG both hold round coordinates) are thus
    // outside for the inside chains and inside for none, so both sides agree.
    const bool meets = clip_segment(p, q, box, t0, t1) && t1 > t0 && strictly_inside(lerp(p, q, 0.5 * (t0 + t1)), box);
    touched |= meets;
    if (keep_inside) {
      if (!meets) {   // an open chain left the box at its last point (on the edge)
        if (cur) end_at(cur->pts.back(), box_param(cur->pts.back(), box));
        continue;
      }
      const geo::LonLat a = lerp(p, q, t0), b = lerp(p, q, t1);
      add(a, box_param(a, box));
      if (t1 < 1 || strictly_outside(q, box)) end_at(b, box_param(b, box));
      else add(b, -1);
    } else {
      if (!meets) {
        // A chain that starts here at a vertex on the box's edge (the ring came out of
        // the box through it) starts on the perimeter: its end takes part in the linking.
        add(p, strictly_outside(p, box) ? -1 : box_param(p, box));
        add(q, -1);
        continue;
      }
      if (t0 > 0) {
        add(p, -1);
        const geo::LonLat a = lerp(p, q, t0);
        end_at(a, box_param(a, box));
      } else if (cur) {
        end_at(p, box_param(p, box));
      }
      if (t1 < 1) {
        const geo::LonLat b = lerp(p, q, t1);
        add(b, box_param(b, box));
        add(q, -1);
      }
    }
  }
  if (!touched) {
    out.resize(first);
    return false;
  }
  if (cur) {
    if (r.closed && first < out.size() && out[first].t_first < 0) {
      // The walk began at a point of this chain: the first chain continues it.
      PatchChain& head = out[first];
      cur->pts.insert(cur->pts.end(), head.pts.begin() + 1, head.pts.end());
      cur->t_last = head.t_last;
      head = std::move(*cur);
    } else if (cur->pts.size() >= 2) {
      out.push_back(std::move(*cur));
    }
  }
  return true;
}

bool ring_contains(const Ring& r, geo::LonLat p) {
  std::vector<Vec2> xy;
  for (auto q : r.pts) xy.push_back({q.lon, q.lat});
  return point_in_ring(xy, {p.lon, p.lat});
}

}  // namespace

Result<std::vector<Ring>> splice_patch(const std::vector<Ring>& base, const std::vector<Ring>& local,
                                       const LonLatBox& box, double radius_m, PatchReport* report) {
  if (!(box.west < box.east && box.south < box.north && box.east - box.west < 360.0 && box.south >= -90 &&
        box.north <= 90))
    return CoastError{"patch", -1,
                      fmt::format("invalid patch box {}/{}/{}/{}: need west < east (less than 360 degrees apart) and "
                                  "-90 <= south < north <= 90",
                                  box.west, box.east, box.south, box.north),
                      {}, coast_option_string(CoastOpt::PatchBox)};
  PatchReport rep;
  std::vector<Ring> out;
  std::vector<PatchChain> chains;
  const geo::LonLat corner{box.west, box.south};
  bool outside_filled = false, inside_filled = false;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const Ring& r = base[i];
    if (r.wraps_pole || is_water(r.level)) {   // not spliced: kept when it stays clear of the box
      std::vector<PatchChain> probe;
      if (!cut_ring(r, i, box, true, probe) && r.closed && !r.pts.empty() && strictly_outside(r.pts[0], box))
        out.push_back(r);
      continue;
    }
    if (!cut_ring(r, i, box, false, chains)) {
      if (!r.pts.empty() && strictly_outside(r.pts[0], box)) {   // wholly outside: kept
        out.push_back(r);
        if (r.closed && ring_contains(r, corner)) outside_filled = !outside_filled;
      }
    }
  }
  rep.base_chains = chains.size();
  for (std::size_t i = 0; i < local.size(); ++i) {
    const Ring& r = local[i];
    if (!r.closed || is_water(r.level) || r.wraps_pole)
      return CoastError{
          "patch", static_cast<std::int64_t>(r.record),
          "a patch shoreline must be closed land rings (level 1): this one is open, a lake or round a pole",
          r.pts.empty() ? std::optional<geo::LonLat>{} : std::optional<geo::LonLat>{r.pts.front()},
          coast_option_string(CoastOpt::Patch)};
    const std::size_t before = chains.size();
    if (!cut_ring(r, base.size() + i, box, true, chains)) {
      if (!strictly_outside(r.pts[0], box)) {   // wholly inside: an island of the patch
        Ring k = r;
        out.push_back(std::move(k));
        ++rep.local_inside;
      } else if (ring_contains(r, corner)) {
        inside_filled = !inside_filled;
      }
    }
    rep.local_chains += chains.size() - before;
  }
  if (rep.local_chains == 0 && rep.local_inside == 0 && !inside_filled)
    return CoastError{"patch", -1,
                      fmt::format("the patch holds no shoreline inside its box {}/{}/{}/{}", box.west, box.east,
                                  box.south, box.north),
                      {}, coast_option_string(CoastOpt::Patch)};
  std::vector<PerimeterChain> ends(chains.size());
  for (std::size_t c = 0; c < chains.size(); ++c) ends[c] = {chains[c].t_first, chains[c].t_last, chains[c].outside};
  const PerimeterLink link = link_along_perimeter(ends, inside_filled, outside_filled);
  if (link.error != PerimeterLinkError::None) {
    const PatchChain& b = chains[link.bad_chain];
    return CoastError{
        "patch",
        static_cast<std::int64_t>(b.ring < base.size() ? base[b.ring].record : local[b.ring - base.size()].record),
        fmt::format("the {} shoreline and the box do not close into land rings here ({})", b.outside ? "base" : "patch",
                    link.error == PerimeterLinkError::Inconsistent
                        ? "two shorelines enter or leave the box in a row: orientations disagree"
                        : "both sides of the box are land or both water at a shoreline's end"),
        b.pts.back(), coast_option_string(CoastOpt::Patch)};
  }
  // Walk: open chains (base polylines cut elsewhere) first, then the closed rings.
  std::vector<char> used(chains.size(), 0);
  auto ring_of = [&](std::size_t c) -> const Ring& {
    return chains[c].ring < base.size() ? base[chains[c].ring] : local[chains[c].ring - base.size()];
  };
  auto walk = [&](std::size_t c0) {
    Ring r;
    r.id = ring_of(c0).id;
    r.record = ring_of(c0).record;
    r.level = 1;
    std::size_t c = c0;
    // Each step uses one chain: at most chains.size() steps.
    while (!used[c]) {
      used[c] = 1;
      for (auto p : chains[c].pts)
        if (r.pts.empty() || !same(r.pts.back(), p)) r.pts.push_back(p);
      if (chains[c].t_last < 0) {
        r.closed = false;
        break;
      }
      const std::size_t nc = link.next[c];
      const geo::LonLat a = chains[c].pts.back(), b = chains[nc].pts.front();
      if (!same(a, b)) {
        std::vector<geo::LonLat> path;
        const double ta = chains[c].t_last, tb = chains[nc].t_first;
        if (link.ccw[c]) {
          path = box_path(a, ta, b, tb == ta ? ta + 4.0 : tb, box, 0.05);
        } else {
          path = box_path(b, tb, a, ta == tb ? tb + 4.0 : ta, box, 0.05);
          std::reverse(path.begin(), path.end());
        }
        const double len = length_m(path, radius_m);
        ++rep.steps;
        if (len > rep.max_step_m) {
          rep.max_step_m = len;
          rep.max_step_at = path[path.size() / 2];
        }
        for (auto p : path)
          if (!same(r.pts.back(), p)) r.pts.push_back(p);
      }
      c = nc;
    }
    if (r.closed && r.pts.size() > 1 && same(r.pts.front(), r.pts.back())) r.pts.pop_back();
    if (r.pts.size() >= (r.closed ? 3u : 2u)) out.push_back(std::move(r));
  };
  for (std::size_t c = 0; c < chains.size(); ++c)
    if (chains[c].t_first < 0 && !used[c]) walk(c);
  for (std::size_t c = 0; c < chains.size(); ++c)
    if (!used[c]) walk(c);
  if (report) *report = rep;
  return out;
}

}  // namespace sm::coast
