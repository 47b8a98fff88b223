// What the import changed, entry by entry (a place, a figure): the log the repair, the
// passages and the import append to. Apart from import.h so that the steps' headers
// (repair.h, passages.h), which import.h holds the options of, need not include it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include "coast/coastline.h"

namespace sm::coast {

enum class RepairKind {
  Refined,        // original points put back on a segment that crossed another
  DroppedIsland,  // island below the accuracy that still touched another loop
  CutSliver,      // a loop meeting itself on the source data: its shorter side cut out
  UnitedIslands,  // two islands overlapping in the source data: replaced by their union
  MergedIslands,  // two islands joined across a strait narrower than the accuracy
  NarrowStrait,   // a strait narrower than strait_factor * gamma, left open
  OutsideWater,   // island outside every outer loop (for instance inland in a region), dropped
  SplineHull,     // original points put back where two B-spline curves crossed or touched
  SplineMayCross, // the B-splines still cross or touch on the source data
  ClosedPassage,  // a passage narrower than passages.min_width closed by dams (width in metres)
  NarrowWater,    // water cut off by a closure, all narrower than passages.min_width: dropped (mean width)
  DamPlaced,      // a dam by hand closing the water it crosses (its length in metres)
  KeptOpen,       // a passage kept open by a KeepOpen point (its width there in metres)
  DroppedSea,     // a sea holding no SeaAt point, dropped (a point inside it, its area in km^2)
  GrazingCrossing,  // a Region polygon edge crossing the shore for less than gamma: no open boundary (length in metres)
  PocketLeftOut,    // water a Region polygon reaches only across such crossings: left out (its area in km^2)
};

struct RepairEntry {
  RepairKind kind;
  std::size_t record;
  std::int64_t id;
  geo::LonLat where;
  double value = 0;   // refined: points added; strait: width in metres
  /// With ImportOptions::min_time_step: a closed or kept-open passage's Courant time step
  /// across it (width / sqrt(g H), seconds); NaN otherwise.
  double step = std::numeric_limits<double>::quiet_NaN();
  /// A KeepOpen passage whose step is under min_time_step: the mesh cannot reach it there.
  bool step_unmet = false;
};

}  // namespace sm::coast
