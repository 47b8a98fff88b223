// Coarsening walk (paper section 2.2; the rule of Gmsh 2.6's Plugin(GSHHS)).
#include "coast/coarsen.h"

#include <cmath>

#include <fmt/format.h>

namespace sm::coast {

double chord(geo::LonLat a, geo::LonLat b, double r) {
  return norm(geo::sphere_from_lonlat(a, r) - geo::sphere_from_lonlat(b, r));
}

double ring_area_km2(const std::vector<geo::LonLat>& pts, double radius_km) {
  // Integral of (1 + sin lat) dlon along the ring, by trapezoids on sin(lat): the area
  // between the ring and the South Pole, so that a pole-wrapping ring gets its own side.
  double a = 0;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = pts[i], q = pts[(i + 1) % n];
    const double dlon = wrap_delta(p.lon, q.lon) * geo::kDegToRad;
    a += dlon * (2.0 + std::sin(p.lat * geo::kDegToRad) + std::sin(q.lat * geo::kDegToRad));
  }
  // The sum runs against the area on the left: minus it is the area left of the ring
  // (a counter-clockwise island, or Antarctica run westwards); a clockwise ring gives a
  // negative value, whose complement is the area on its left.
  a = -0.5 * a * radius_km * radius_km;
  const double sphere = 4.0 * geo::kPi * radius_km * radius_km;
  if (a < 0) a += sphere;
  if (a > sphere) a -= sphere;
  return a;
}

Result<CoarsenResult> coarsen(std::vector<Ring> rings, const CoarsenOptions& opt) {
  if (!opt.gamma) return CoastError{"coarsen", -1, "no accuracy field given", {}};
  if (!(opt.radius > 0)) return CoastError{"coarsen", -1, "the sphere radius must be positive", {}};
  CoarsenResult out;
  const double r = opt.radius;
  std::vector<Vec3> xyz;
  for (Ring& ring : rings) {
    const std::size_t n = ring.pts.size();
    out.points_in += n;
    if (n == 0) continue;   // nothing to keep (clean() never leaves such rings)
    if (ring.closed && opt.min_area_km2 > 0) {
      const double area = ring_area_km2(ring.pts, r * 1e-3);
      if (area < opt.min_area_km2) {
        out.dropped.push_back({ring.record, ring.id, DropReason::BelowMinArea, ring.pts.front(), area});
        continue;
      }
    }
    xyz.resize(n);
    for (std::size_t i = 0; i < n; ++i) xyz[i] = geo::sphere_from_lonlat(ring.pts[i], r);
    CoarseRing cr;
    cr.gamma.assign(n, 0.0);
    opt.gamma(xyz, cr.gamma);
    for (std::size_t i = 0; i < n; ++i)
      if (!(cr.gamma[i] > 0) || !std::isfinite(cr.gamma[i]))
        return CoastError{"coarsen", static_cast<std::int64_t>(ring.record),
                          fmt::format("the accuracy field gives {} (must be finite and > 0)", cr.gamma[i]),
                          ring.pts[i]};
    auto& keep = cr.keep;
    keep.push_back(0);
    std::size_t last = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (norm(xyz[i] - xyz[last]) >= cr.gamma[i]) {
        keep.push_back(static_cast<std::uint32_t>(i));
        last = i;
      }
    }
    if (ring.closed) {
      while (keep.size() > 1 && norm(xyz[keep.back()] - xyz[0]) < cr.gamma[keep.back()]) keep.pop_back();
      if (keep.size() < opt.min_points) {
        out.dropped.push_back({ring.record, ring.id, DropReason::TooFewPoints, ring.pts.front(),
                               ring_area_km2(ring.pts, r * 1e-3)});
        continue;
      }
    } else if (keep.back() != n - 1) {
      if (keep.size() > 1 && norm(xyz[keep.back()] - xyz[n - 1]) < cr.gamma[n - 1]) keep.pop_back();
      keep.push_back(static_cast<std::uint32_t>(n - 1));
    }
    out.points_out += keep.size();
    cr.ring = std::move(ring);
    out.rings.push_back(std::move(cr));
  }
  return out;
}

}  // namespace sm::coast
