// Consistency repair of coarsened coastline loops: segments that cross after
// coarsening get their original points back (the source data is self-consistent, so
// this converges at the latest on the original shoreline); islands below the accuracy
// that still touch are dropped; narrow straits are listed or closed by merging islands.
#pragma once

#include <cstdint>
#include <vector>

#include "coast/coastline.h"
#include "coast/coarsen.h"
#include "coast/repair_entry.h"

namespace sm::coast {

/// A curve during repair: full-resolution points, gamma at each, retained indices.
struct WorkCurve {
  std::vector<geo::LonLat> full;
  std::vector<Vec2> uv;                 // (u,v) of every full point
  std::vector<double> gamma;
  std::vector<std::uint32_t> keep;      // increasing; periodic curves close keep.back() -> keep[0]
  bool periodic = false;
  bool open_boundary = false;
  std::size_t record = 0;
  std::int64_t id = -1;
};

/// Frees a curve's points (their capacity too): for a curve no live loop uses any more,
/// whose 40 bytes a source point would otherwise stay allocated to the end of the import.
void free_points(WorkCurve& c);

struct WorkLoop {
  std::vector<std::uint32_t> curves;    // consecutive; a non-periodic curve ends where the next starts
  bool hole = true;
  bool dead = false;
};

struct RepairOptions {
  int max_rounds = 64;
  double radius = geo::kEarthRadius;
  double strait_factor = 1.0;
  bool close_straits = false;
  /// Also refine where the B-spline curves cross or touch (find_spline_crossings); places
  /// left on original data are reported as SplineMayCross.
  bool check_splines = true;
  int threads = 1;   // for the spline check (find_spline_crossings) and the straits' search: the same result for any
};

/// The (u,v) polygon of a loop (first point not repeated) and, per vertex, the curve and
/// keep position it comes from.
struct LoopVertexRef {
  std::uint32_t curve, k;
};
void loop_polygon(const std::vector<WorkCurve>& curves, const WorkLoop& loop, std::vector<Vec2>& uv,
                  std::vector<LoopVertexRef>* refs);

/// Repairs in place; appends what changed to `log`. Returns the number of rounds, or an
/// error naming the loops and the place when an intersection survives on original data.
Result<std::size_t> repair_loops(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops,
                                 const RepairOptions& opt, std::vector<RepairEntry>& log);

/// Straits narrower than strait_factor * gamma between two loops (or two far-apart parts
/// of one loop), measured on the sphere (uv distance times the conformal factor). Each
/// pair of loops is reported once (NarrowStrait, width in metres) at its narrowest place.
/// With close_straits, two islands facing each other across such a strait are merged
/// into one loop: the two facing segments are replaced by the two bridge edges joining
/// their ends, closing the strait (a merge that would cross anything is not made, and
/// the strait is reported instead). Call on repaired (intersection-free) loops.
void handle_straits(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops, const RepairOptions& opt,
                    std::vector<RepairEntry>& log);

}  // namespace sm::coast
