// Longitude bookkeeping shared by the readers, and error formatting.
#include "coast/coastline.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace sm::coast {

std::string CoastError::to_string() const {
  std::string s = file.empty() ? std::string("coastline") : file;
  if (record >= 0) s += fmt::format(": record {}", record);
  if (where) s += fmt::format(" (lon {:.6f}, lat {:.6f})", where->lon, where->lat);
  s += ": " + message;
  return s;
}

double wrap_delta(double a, double b) {
  double d = std::fmod(b - a, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

void unwrap_longitudes(std::vector<geo::LonLat>& pts) {
  if (pts.empty()) return;
  double lo = pts[0].lon, hi = pts[0].lon;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    // Shift by a whole number of turns (never accumulate differences: a ring that
    // comes back to its start must come back to the same double). A step under 180
    // degrees rounds to no turn, so the usual case skips the division (a zero longitude
    // takes the formula still: adding +-0 may change the sign of its zero).
    const double step = pts[i - 1].lon - pts[i].lon;
    if (!(std::abs(step) < 180.0) || pts[i].lon == 0.0) pts[i].lon += 360.0 * std::round(step / 360.0);
    lo = std::min(lo, pts[i].lon);
    hi = std::max(hi, pts[i].lon);
  }
  const double mid = 0.5 * (lo + hi);
  const double shift = -360.0 * std::floor((mid + 180.0) / 360.0);
  if (shift != 0)
    for (auto& p : pts) p.lon += shift;
}

double longitude_winding(const std::vector<geo::LonLat>& pts) {
  if (pts.size() < 2) return 0;
  double w = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& a = pts[i];
    const auto& b = pts[(i + 1) % pts.size()];
    w += wrap_delta(a.lon, b.lon);
  }
  return 360.0 * std::round(w / 360.0);
}

bool same_point(geo::LonLat a, geo::LonLat b) {
  if (a.lat != b.lat) return false;
  if (a.lon == b.lon || std::abs(a.lat) == 90.0) return true;   // the first test spares the fmod
  return wrap_delta(a.lon, b.lon) == 0.0;
}

void normalise_ring(Ring& r) {
  unwrap_longitudes(r.pts);
  if (r.closed && r.pts.size() >= 2 && same_point(r.pts.front(), r.pts.back())) r.pts.pop_back();
  r.wraps_pole = r.closed && longitude_winding(r.pts) != 0.0;
}

}  // namespace sm::coast
