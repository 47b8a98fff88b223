// Test/bench helper: GSHHG text rings (data/gshhg) as a
// BoundaryProblem in the paper's stereographic plane (unit sphere, from the
// South Pole), either on the raw vertices or resampled at a uniform step.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/boundary_recovery.h"
#include "mesh/cdt.h"

namespace sm::testing {

struct Ring {
  std::vector<double> lon, lat;  // as in the file; closed rings repeat the first vertex
  bool wraps_pole = false;
};

inline std::vector<Ring> read_gshhg(const std::string& path) {
  std::vector<Ring> rings;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '>') {
      rings.emplace_back();
      rings.back().wraps_pole = line.find("wraps_pole=1") != std::string::npos;
      continue;
    }
    double lo, la;
    if (!rings.empty() && std::sscanf(line.c_str(), "%lf %lf", &lo, &la) == 2) {
      rings.back().lon.push_back(lo);
      rings.back().lat.push_back(la);
    }
  }
  // The data has zero-width spikes A B A where GMT bin pieces were joined
  // (world_c.txt seg 1 at lon 0, lat 49.33): remove B and the repeated A.
  for (Ring& r : rings) {
    std::vector<double> lo, la;
    for (std::size_t k = 0; k < r.lon.size(); ++k) {
      const std::size_t n = lo.size();
      if (n >= 2 && lo[n - 2] == r.lon[k] && la[n - 2] == r.lat[k]) {
        lo.pop_back(), la.pop_back();
        continue;
      }
      lo.push_back(r.lon[k]), la.push_back(r.lat[k]);
    }
    r.lon = lo, r.lat = la;
  }
  // Drop the simplification artefacts: rings with fewer than 3 distinct vertices.
  std::erase_if(rings, [](const Ring& r) { return r.lon.size() < 4; });
  return rings;
}

inline Vec2 stereo(double lon_deg, double lat_deg) {
  const double lo = lon_deg * M_PI / 180, la = lat_deg * M_PI / 180;
  const double x = std::cos(la) * std::cos(lo), y = std::cos(la) * std::sin(lo), z = std::sin(la);
  return {x / (1 + z), y / (1 + z)};
}

inline double great_circle_km(double lon1, double lat1, double lon2, double lat2) {
  const double r = M_PI / 180;
  const double s1 = std::sin((lat2 - lat1) * r / 2), s2 = std::sin((lon2 - lon1) * r / 2);
  const double a = s1 * s1 + std::cos(lat1 * r) * std::cos(lat2 * r) * s2 * s2;
  return 2 * 6371.0 * std::asin(std::min(1.0, std::sqrt(a)));
}

/// A ring as a curve: parameter = length along the polyline (km), points
/// linear in lon/lat within each segment.
struct RingCurve {
  const Ring* ring;
  std::vector<double> s;  // cumulative length at each vertex
  explicit RingCurve(const Ring& r) : ring(&r), s(r.lon.size(), 0.0) {
    for (std::size_t k = 1; k < r.lon.size(); ++k)
      s[k] = s[k - 1] + great_circle_km(r.lon[k - 1], r.lat[k - 1], r.lon[k], r.lat[k]);
  }
  double length() const { return s.back(); }
  Vec2 at(double t) const {
    const std::size_t k = std::min<std::size_t>(
        std::upper_bound(s.begin(), s.end(), t) - s.begin(), s.size() - 1);
    const std::size_t j = k == 0 ? 0 : k - 1;
    const double len = s[j + 1] - s[j], f = len > 0 ? std::clamp((t - s[j]) / len, 0.0, 1.0) : 0.0;
    return stereo(ring->lon[j] + f * (ring->lon[j + 1] - ring->lon[j]),
                  ring->lat[j] + f * (ring->lat[j + 1] - ring->lat[j]));
  }
};

/// Each ring becomes one closed curve: the raw vertices (step_km = 0) or
/// max(3, round(length / step)) points evenly spaced along it.
inline BoundaryProblem coast_problem(const std::vector<RingCurve>& curves, double step_km) {
  BoundaryProblem p;
  for (std::uint32_t c = 0; c < curves.size(); ++c) {
    const RingCurve& rc = curves[c];
    BoundaryCurve cv;
    cv.id = c + 1;
    const auto first = static_cast<std::uint32_t>(p.points.size());
    if (step_km <= 0) {
      for (std::size_t k = 0; k + 1 < rc.s.size(); ++k) {
        cv.pts.push_back(static_cast<std::uint32_t>(p.points.size()));
        p.points.push_back(stereo(rc.ring->lon[k], rc.ring->lat[k]));
        cv.t.push_back(rc.s[k]);
      }
    } else {
      const int n = std::max(3, static_cast<int>(std::lround(rc.length() / step_km)));
      for (int k = 0; k < n; ++k) {
        const double t = rc.length() * k / n;
        cv.pts.push_back(static_cast<std::uint32_t>(p.points.size()));
        p.points.push_back(rc.at(t));
        cv.t.push_back(t);
      }
    }
    cv.pts.push_back(first);  // closed (the pole-wrapping ring closes on the sphere)
    cv.t.push_back(rc.length());
    p.curves.push_back(std::move(cv));
  }
  return p;
}

/// The loops of the ocean domain of coast_problem(curves of rings): the ring round the
/// South Pole (Antarctica's ice front, the largest loop in this plane) is the outer loop,
/// every other ring an island, for remove_outside.
inline std::vector<Loop> ocean_loops(const BoundaryProblem& p, const std::vector<Ring>& rings) {
  std::vector<Loop> loops;
  for (std::size_t c = 0; c < p.curves.size(); ++c) {
    Loop l;
    for (std::size_t k = 0; k + 1 < p.curves[c].pts.size(); ++k) l.v.push_back(VertexId{p.curves[c].pts[k]});
    l.hole = !rings[c].wraps_pole;
    loops.push_back(std::move(l));
  }
  return loops;
}

}  // namespace sm::testing
