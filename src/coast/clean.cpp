// Ring cleaning: a single stack pass per ring removes duplicates and spikes (a spike
// uncovered by removing another is caught by the same stack), then the closing seam of a
// closed ring is checked the same way until nothing changes.
#include "coast/clean.h"

#include <fmt/format.h>

namespace sm::coast {

std::size_t CleanReport::count(CleanAction a) const {
  std::size_t n = 0;
  for (const auto& e : entries) n += e.action == a;
  return n;
}

std::string CleanReport::summary() const {
  return fmt::format("{} duplicate vertices, {} spikes, {} south-pole vertices removed; {} degenerate rings dropped",
                     count(CleanAction::Duplicate), count(CleanAction::Spike), count(CleanAction::PoleVertex),
                     count(CleanAction::DegenerateRing));
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

}  // namespace sm::coast
