// Adaptive coarsening of shorelines with an accuracy field gamma(x) (paper section 2.2):
// walking each ring, successive points closer than gamma are collapsed; rings too small
// for the accuracy, or below a minimum area, are dropped.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "base/vec.h"
#include "coast/coastline.h"

namespace sm::coast {

/// gamma at 3D points of the sphere of radius CoarsenOptions::radius (metres), in batches:
/// the interpreter passes any size field through this.
using AccuracyFn = std::function<void(std::span<const Vec3> pts, std::span<double> gamma)>;

struct CoarsenOptions {
  AccuracyFn gamma;
  double radius = geo::kEarthRadius;   // metres
  double min_area_km2 = 0;             // closed rings of smaller spherical area are dropped
  /// A closed ring survives only with at least this many points after coarsening: 3, the
  /// rule of the paper's tool (a ring of 3 points spaced >= gamma has a perimeter >= 3 gamma);
  /// it reproduces Figure 5 (docs/coastlines.md).
  std::size_t min_points = 3;
  /// Threads for the walk over the rings (the accuracy field is still called from the
  /// calling thread only); the result is the same for every count. <= 0: all cores.
  int threads = 1;
};

/// One ring after coarsening. The full-resolution ring is kept with the indices of the
/// retained points so that repair can put original points back where needed.
struct CoarseRing {
  Ring ring;                          // cleaned, full resolution
  std::vector<std::uint32_t> keep;    // increasing indices into ring.pts
  std::vector<double> gamma;          // gamma at every point of ring.pts (metres)
};

enum class DropReason { TooFewPoints, BelowMinArea };

struct DroppedRing {
  std::size_t record;
  std::int64_t id;
  DropReason reason;
  geo::LonLat where;   // first point
  double area_km2;
};

struct CoarsenResult {
  std::vector<CoarseRing> rings;
  std::vector<DroppedRing> dropped;
  std::size_t points_in = 0, points_out = 0;
};

/// Chord length is the distance (as Gmsh's plugin): for gamma << R it differs from the
/// great-circle length by a factor 1 - theta^2/24 (1e-5 at 100 km), well below any use.
/// A point is kept when its chord to the last kept point is at least its own gamma; for a
/// closed ring, trailing points closer than their gamma to the first point are dropped
/// (the closing segment obeys the same rule). Open polylines keep both end points (they
/// lie on a region boundary). A non-finite or non-positive gamma is an error.
Result<CoarsenResult> coarsen(std::vector<Ring> rings, const CoarsenOptions& opt);

/// Spherical area on the LEFT of a closed ring (contiguous longitudes), km^2 on a sphere
/// of radius radius_km: an island run counter-clockwise, Antarctica run westwards.
double ring_area_km2(const std::vector<geo::LonLat>& pts, double radius_km);

/// Chord length between two lon/lat points on the sphere of radius r.
double chord(geo::LonLat a, geo::LonLat b, double r);

}  // namespace sm::coast
