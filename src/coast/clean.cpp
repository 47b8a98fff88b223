// Ring cleaning: a single stack pass per ring removes duplicates and spikes (a spike
// uncovered by removing another is caught by the same stack), then the closing seam of a
// closed ring is checked the same way until nothing changes.
#include "coast/clean.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace sm::coast {

std::size_t CleanReport::count(CleanAction a) const {
  std::size_t n = 0;
  for (const auto& e : entries) n += e.action == a;
  return n;
}

std::string CleanReport::summary() const {
  return fmt::format(
      "{} duplicate vertices, {} spikes, {} south-pole vertices removed; {} degenerate rings dropped; "
      "{} rings sharing an edge merged",
      count(CleanAction::Duplicate), count(CleanAction::Spike), count(CleanAction::PoleVertex),
      count(CleanAction::DegenerateRing), count(CleanAction::MergedRings));
}

namespace {

void clean_ring(Ring& r, CleanReport& rep) {
  auto note = [&](CleanAction a, geo::LonLat p) { rep.entries.push_back({a, r.record, r.id, p}); };
  // Natural Earth closes Antarctica along the South Pole: those vertices are the singular
  // point of the projection and carry no shoreline.
  if (r.closed) {
    std::vector<geo::LonLat> kept;
    kept.reserve(r.pts.size());
    for (auto p : r.pts) {
      if (p.lat == -90.0)
        note(CleanAction::PoleVertex, p);
      else
        kept.push_back(p);
    }
    if (kept.size() != r.pts.size()) {
      r.pts = std::move(kept);
      r.wraps_pole = longitude_winding(r.pts) != 0.0;
    }
  }
  std::vector<geo::LonLat> out;
  out.reserve(r.pts.size());
  for (auto p : r.pts) {
    if (!out.empty() && same_point(out.back(), p)) {
      note(CleanAction::Duplicate, p);
      continue;
    }
    if (out.size() >= 2 && same_point(out[out.size() - 2], p)) {
      note(CleanAction::Spike, out.back());
      out.pop_back();
      continue;
    }
    out.push_back(p);
  }
  if (r.closed) {
    bool changed = true;
    while (changed && out.size() >= 3) {
      changed = false;
      const std::size_t n = out.size();
      if (same_point(out[n - 1], out[0])) {
        note(CleanAction::Duplicate, out[n - 1]);
        out.pop_back();
        changed = true;
      } else if (same_point(out[n - 2], out[0])) {        // spike at out[n-1]
        note(CleanAction::Spike, out[n - 1]);
        out.resize(n - 2);
        changed = true;
      } else if (same_point(out[n - 1], out[1])) {        // spike at out[0]
        note(CleanAction::Spike, out[0]);
        out.erase(out.begin(), out.begin() + 2);
        changed = true;
      }
    }
  }
  r.pts = std::move(out);
}

}  // namespace

CleanReport clean(Coastline& c) {
  CleanReport rep;
  std::vector<Ring> kept;
  kept.reserve(c.rings.size());
  for (Ring& r : c.rings) {
    clean_ring(r, rep);
    const std::size_t need = r.closed ? 3 : 2;
    if (r.pts.size() < need) {
      rep.entries.push_back({CleanAction::DegenerateRing, r.record, r.id,
                             r.pts.empty() ? geo::LonLat{} : r.pts.front()});
      continue;
    }
    kept.push_back(std::move(r));
  }
  c.rings = std::move(kept);
  return rep;
}

namespace {

// A point with its longitude folded into [0,360) (poles: lon 0), comparable exactly.
struct Key {
  double lon, lat;
  friend bool operator<(Key a, Key b) { return a.lon != b.lon ? a.lon < b.lon : a.lat < b.lat; }
  friend bool operator==(Key a, Key b) { return a.lon == b.lon && a.lat == b.lat; }
};

Key key(geo::LonLat p) {
  if (std::abs(p.lat) == 90.0) return {0.0, p.lat};
  double l = std::fmod(p.lon, 360.0);
  if (l < 0) l += 360.0;
  // Snap to 1e-9 degree (0.1 mm): Natural Earth writes the dateline as 180.00000000000014.
  l = std::round(l * 1e9) * 1e-9;
  if (l >= 360.0) l -= 360.0;
  return {l, p.lat};
}

struct Edge {
  Key a, b;
  std::uint32_t ring, index;
  friend bool operator<(const Edge& x, const Edge& y) {
    if (!(x.a == y.a)) return x.a < y.a;
    if (!(x.b == y.b)) return x.b < y.b;
    return x.ring != y.ring ? x.ring < y.ring : x.index < y.index;
  }
};

}  // namespace

// Polygons cut at the dateline do not always carry the same vertices along the cut:
// every vertex lying on lon +-180 is inserted into the dateline edges of the other rings
// that pass over it, so that the shared runs become identical edges.
void split_dateline_edges(Coastline& c) {
  std::vector<double> lats;
  for (const Ring& r : c.rings)
    if (r.closed && !r.wraps_pole)
      for (auto p : r.pts)
        if (key(p).lon == 180.0) lats.push_back(p.lat);
  if (lats.empty()) return;
  std::sort(lats.begin(), lats.end());
  lats.erase(std::unique(lats.begin(), lats.end()), lats.end());
  for (Ring& r : c.rings) {
    if (!r.closed || r.wraps_pole) continue;
    const std::size_t n = r.pts.size();
    std::vector<geo::LonLat> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const geo::LonLat a = r.pts[i], b = r.pts[(i + 1) % n];
      out.push_back(a);
      if (key(a).lon != 180.0 || key(b).lon != 180.0 || std::abs(a.lon - b.lon) > 1e-6) continue;
      const double lo = std::min(a.lat, b.lat), hi = std::max(a.lat, b.lat);
      auto first = std::upper_bound(lats.begin(), lats.end(), lo);
      auto last = std::lower_bound(lats.begin(), lats.end(), hi);
      if (first >= last) continue;
      if (a.lat < b.lat)
        for (auto it = first; it != last; ++it) out.push_back({a.lon, *it});
      else
        for (auto it = last; it != first; --it) out.push_back({a.lon, *(it - 1)});
    }
    r.pts = std::move(out);
  }
}

void merge_touching_rings(Coastline& c, CleanReport& rep) {
  split_dateline_edges(c);
  for (;;) {
    std::vector<Edge> edges;
    for (std::uint32_t r = 0; r < c.rings.size(); ++r) {
      const Ring& ring = c.rings[r];
      if (!ring.closed || ring.wraps_pole) continue;
      const auto n = static_cast<std::uint32_t>(ring.pts.size());
      for (std::uint32_t i = 0; i < n; ++i) edges.push_back({key(ring.pts[i]), key(ring.pts[(i + 1) % n]), r, i});
    }
    std::sort(edges.begin(), edges.end());
    std::vector<char> busy(c.rings.size(), 0), dead(c.rings.size(), 0);
    bool merged = false;
    for (const Edge& e : edges) {
      if (busy[e.ring]) continue;
      // The same edge run the other way in another ring of the same level.
      auto it = std::lower_bound(edges.begin(), edges.end(), Edge{e.b, e.a, 0, 0});
      for (; it != edges.end() && it->a == e.b && it->b == e.a; ++it) {
        if (it->ring == e.ring || busy[it->ring] || c.rings[it->ring].level != c.rings[e.ring].level) continue;
        Ring& A = c.rings[e.ring];
        Ring& B = c.rings[it->ring];
        // A: ... p=A[i] -> q=A[i+1] ...; B: ... q=B[j] -> p=B[j+1] ...
        // Merged: A from q round to p, then B from after p round to before q.
        const std::size_t na = A.pts.size(), nb = B.pts.size();
        std::vector<geo::LonLat> pts;
        pts.reserve(na + nb);
        for (std::size_t k = 0; k < na; ++k) pts.push_back(A.pts[(e.index + 1 + k) % na]);
        for (std::size_t k = 2; k < nb; ++k) pts.push_back(B.pts[(it->index + k) % nb]);
        rep.entries.push_back({CleanAction::MergedRings, B.record, B.id, A.pts[e.index]});
        A.pts = std::move(pts);
        unwrap_longitudes(A.pts);
        A.area_km2 = A.area_km2 + B.area_km2;
        busy[e.ring] = busy[it->ring] = 1;
        dead[it->ring] = 1;
        merged = true;
        break;
      }
    }
    if (!merged) return;
    std::vector<Ring> kept;
    for (std::size_t r = 0; r < c.rings.size(); ++r)
      if (!dead[r]) kept.push_back(std::move(c.rings[r]));
    c.rings = std::move(kept);
    // The rest of a shared run now folds back on itself: the spike pass removes it.
    for (Ring& r : c.rings) clean_ring(r, rep);
  }
}

}  // namespace sm::coast
