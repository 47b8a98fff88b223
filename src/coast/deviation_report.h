// What the deviation pass (coast/deviation.h) found, apart from the pass itself so that
// the import's report can carry it.
#pragma once

#include <cstddef>

#include "geo/sphere.h"

namespace sm::coast {

/// Where the curves stand against the source data after the pass, in metres on the sphere
/// (chords of the sphere of `radius`).
struct DeviationReport {
  double max_before = 0;              ///< largest distance of a source point from the curve, before
  double max = 0;                     ///< the same after the pass, narrow features apart
  double p95 = 0;                     ///< 95% of the source points lie within this of the curve
  double max_ratio = 0;               ///< largest distance / bound after the pass
  geo::LonLat where{};                ///< the source point of `max`
  std::size_t points_added = 0;       ///< control points put back (split points included)
  /// Segments of the data with no point left between two control points, split at their
  /// middle to bring the curve to a bend (counted in points_added too).
  std::size_t segments_split = 0;
  std::size_t curves_changed = 0;
  std::size_t left_over_bound = 0;    ///< spans still over the bound with no point left to put back
  geo::LonLat where_over{};           ///< the first of those (by curve order)
  /// Spans over the bound where every source point to put back would make a corner
  /// sharper than DeviationOptions::min_angle_deg: inlets and spits narrower than the
  /// accuracy, left out of the curve as coarsening leaves them.
  std::size_t narrow_features = 0;
  geo::LonLat where_narrow{};         ///< the farthest source point of the first of those
  double narrow_max = 0;              ///< the farthest source point of all of those (m)
  int rounds = 0;
};

}  // namespace sm::coast
