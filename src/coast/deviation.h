// The coast curve kept within a distance of the source shoreline. Coarsening keeps points
// at least gamma apart and the B-spline through them cuts every convex bend (it passes
// near, not through, its control points), so on its own the curve strays from the data by
// several gamma at headlands, and a strait between two headlands comes out wider than it
// is. This pass measures, curve by curve, how far the curve the mesher will follow lies
// from the full-resolution points between its control points (and they from it), and puts
// the farthest source point back as a control point wherever the distance exceeds the
// bound, until every span holds or no source point is left to put back.
#pragma once

#include <cstddef>
#include <vector>

#include "coast/deviation_report.h"
#include "coast/repair.h"

namespace sm::coast {

struct DeviationOptions {
  double radius = geo::kEarthRadius;   ///< metres
  /// The bound at a source point: `factor` times gamma there, or `fixed` metres when > 0
  /// (Coastline[n].MaxDeviation).
  double factor = 0.5;
  double fixed = 0;
  /// The curve between control points: the uniform cubic B-spline Gmsh draws
  /// (geo/curve_bspline.h; periodic curves wrap, pieces have their end points tripled),
  /// or straight segments (CurveType "Line").
  bool bspline = true;
  /// Rounds of putting points back over the curves that still stray (each round puts back
  /// at least one point on each such curve, so the total is also bounded by the points).
  int max_rounds = 32;
  /// No point is put back where it would make a corner sharper than this (degrees) at
  /// itself or at a neighbour that was not that sharp already.
  double min_angle_deg = 30;
  int threads = 1;
};

/// Puts source points back into `keep` of every coast curve (not the region's box pieces)
/// until the curve lies within the bound of its source points. The same result for every
/// thread count.
DeviationReport bound_deviation(std::vector<WorkCurve>& curves, const DeviationOptions& opt);

/// Distance (metres) from each source point of `c` to the curve drawn through its control
/// points (the pass's own measure, for tests and the report).
std::vector<double> source_distances(const WorkCurve& c, const DeviationOptions& opt);

}  // namespace sm::coast
