// Coarsening walk (paper section 2.2; the rule of Gmsh 2.6's Plugin(GSHHS)).
#include "coast/coarsen.h"

#include <cmath>

#include <fmt/format.h>

#include "base/parallel.h"

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

namespace {

// What the walk made of one ring: nothing (no point), a dropped ring, a kept one, or an
// accuracy that is not a length.
struct Outcome {
  enum Kind { Empty, Dropped, Kept, BadGamma } kind = Empty;
  DroppedRing dropped{};
  CoarseRing kept;
  std::size_t bad = 0;   // BadGamma: the point
};

// The walk itself on one ring whose points (xyz) and accuracies (out.kept.gamma) are known.
void walk(const Ring& ring, const std::vector<Vec3>& xyz, const CoarsenOptions& opt, Outcome& out) {
  const std::size_t n = ring.pts.size();
  CoarseRing& cr = out.kept;
  for (std::size_t i = 0; i < n; ++i)
    if (!(cr.gamma[i] > 0) || !std::isfinite(cr.gamma[i])) {
      out.kind = Outcome::BadGamma;
      out.bad = i;
      return;
    }
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
      out.kind = Outcome::Dropped;
      out.dropped = {ring.record, ring.id, DropReason::TooFewPoints, ring.pts.front(),
                     ring_area_km2(ring.pts, opt.radius * 1e-3)};
      return;
    }
  } else if (keep.back() != n - 1) {
    if (keep.size() > 1 && norm(xyz[keep.back()] - xyz[n - 1]) < cr.gamma[n - 1]) keep.pop_back();
    keep.push_back(static_cast<std::uint32_t>(n - 1));
  }
  out.kind = Outcome::Kept;
}

}  // namespace

Result<CoarsenResult> coarsen(std::vector<Ring> rings, const CoarsenOptions& opt) {
  if (!opt.gamma) return CoastError{"coarsen", -1, "no accuracy field given", {}};
  if (!(opt.radius > 0)) return CoastError{"coarsen", -1, "the sphere radius must be positive", {}};
  CoarsenResult out;
  const double r = opt.radius;
  const int threads = resolve_thread_count(opt.threads);
  // Rings go in groups of about a million points: the points on the sphere and the walk
  // run in parallel over the rings of a group, the accuracy field is called between the
  // two on the calling thread, ring by ring in order (the same calls as one thread makes:
  // the field need not be callable from several threads), and the outcomes are taken in
  // ring order. Group and chunk bounds depend on the rings only: the same result for every
  // thread count.
  constexpr std::size_t kGroupPoints = std::size_t{1} << 20, kChunk = 16;
  std::vector<std::vector<Vec3>> xyz;
  std::vector<Outcome> outcome;
  for (std::size_t g0 = 0; g0 < rings.size();) {
    std::size_t g1 = g0, points = 0;
    while (g1 < rings.size() && (g1 == g0 || points < kGroupPoints)) points += rings[g1++].pts.size();
    const std::size_t m = g1 - g0;
    xyz.assign(m, {});
    outcome.assign(m, {});
    std::vector<char> needs_gamma(m, 0);
    parallel_for_chunks(threads, m, kChunk, [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) {
        const Ring& ring = rings[g0 + k];
        const std::size_t n = ring.pts.size();
        if (n == 0) continue;   // nothing to keep (clean() never leaves such rings)
        if (ring.closed && opt.min_area_km2 > 0) {
          const double area = ring_area_km2(ring.pts, r * 1e-3);
          if (area < opt.min_area_km2) {
            outcome[k].kind = Outcome::Dropped;
            outcome[k].dropped = {ring.record, ring.id, DropReason::BelowMinArea, ring.pts.front(), area};
            continue;
          }
        }
        xyz[k].resize(n);
        for (std::size_t i = 0; i < n; ++i) xyz[k][i] = geo::sphere_from_lonlat(ring.pts[i], r);
        needs_gamma[k] = 1;
      }
    });
    for (std::size_t k = 0; k < m; ++k)
      if (needs_gamma[k]) {
        outcome[k].kept.gamma.assign(xyz[k].size(), 0.0);
        opt.gamma(xyz[k], outcome[k].kept.gamma);
      }
    parallel_for_chunks(threads, m, kChunk, [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k)
        if (needs_gamma[k]) {
          walk(rings[g0 + k], xyz[k], opt, outcome[k]);
          std::vector<Vec3>().swap(xyz[k]);
        }
    });
    for (std::size_t k = 0; k < m; ++k) {
      Ring& ring = rings[g0 + k];
      Outcome& o = outcome[k];
      out.points_in += ring.pts.size();
      switch (o.kind) {
        case Outcome::Empty: break;
        case Outcome::BadGamma:
          return CoastError{"coarsen", static_cast<std::int64_t>(ring.record),
                            fmt::format("the accuracy field gives {} (must be finite and > 0)", o.kept.gamma[o.bad]),
                            ring.pts[o.bad]};
        case Outcome::Dropped: out.dropped.push_back(o.dropped); break;
        case Outcome::Kept:
          out.points_out += o.kept.keep.size();
          o.kept.ring = std::move(ring);
          out.rings.push_back(std::move(o.kept));
          break;
      }
    }
    g0 = g1;
  }
  return out;
}

}  // namespace sm::coast
