// The coastline import pipeline (paper section 2.2): level filter, cleaning,
// orientation, region clipping, coarsening with gamma(x), topology on the sphere, and
// intersection repair. Produces loops in PolarSphere (u,v) coordinates ready to become
// periodic B-splines; this is the kernel behind `Coastline[n] = ...; loops[] = Coastline{n};`.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "base/progress.h"
#include "coast/clean.h"
#include "coast/coarsen.h"
#include "coast/coastline.h"
#include "coast/deviation.h"
#include "coast/deviation_report.h"
#include "coast/passages.h"
#include "coast/repair.h"
#include "coast/repair_entry.h"
#include "coast/patch.h"
#include "coast/region.h"

namespace sm::coast {

/// The import's options: the context every step shares (gamma, radius, threads,
/// progress), the source (levels, region, patch) and one struct per step, which the step
/// receives as it is (build_coast_model fills in only the shared context: radius,
/// threads and gamma are the import's, whatever the step's own copy holds).
struct ImportOptions {
  std::vector<int> levels{1};          // GSHHS levels kept
  /// Antarctica in GSHHG >= 2.3 binaries is level 5 (ice front) or 6 (grounding line),
  /// outside `levels`: the level kept for it (0 = none). Text exports use level 1.
  int antarctica_level = 5;
  AccuracyFn gamma;                    // metres at 3D points of the sphere of `radius`
  double radius = geo::kEarthRadius;   // metres
  /// Threads for the steps that work ring by ring (cleaning, coarsening, the deviation
  /// pass; the accuracy field is called from the calling thread only): the result is
  /// the same for every count (base/parallel.h). <= 0: the hardware concurrency.
  int threads = 1;
  std::optional<LonLatBox> region;     // clip to this box
  /// Clip to this polygon instead (great-circle edges, region_polygon.h) when it has
  /// vertices; `region` is then its bounding box, for the readers.
  std::vector<geo::LonLat> region_polygon;
  /// A local shoreline replacing the data inside patch_box (patch.h): land = (data's land
  /// outside the box) U (patch land inside it). Set both or neither.
  std::vector<Ring> patch;
  std::optional<LonLatBox> patch_box;
  bool use_file_region = true;         // else clip to the file's own -R box when it has open pieces
  RegionOptions region_options;
  /// Rings too small for gamma or below min_area_km2 are dropped (coarsen.h). Closed
  /// pieces of a region loop are coarsened with min_area_km2 0 and min_points 3.
  CoarsenOptions coarsen;
  /// The coast curve kept within deviation.factor times gamma of the source points, or
  /// deviation.fixed metres when > 0 (deviation.h; 0.5 by default: within gamma / 2; 0
  /// measures and reports only, see docs/coastlines.md); the curve type measured is the
  /// B-spline, or the control polygon when deviation.bspline is false.
  DeviationOptions deviation;
  /// Crossings put back on the source data, straits narrower than strait_factor * gamma
  /// (Gmsh's MinStraitsFactor) reported or, with close_straits, merged; check_splines:
  /// also where the B-splines through the control points cross or come within 1e-3 gamma
  /// (spline_check.h; docs/coastlines.md 6).
  RepairOptions repair;
  /// Passages narrower than passages.min_width (metres) closed by dams, dams by hand,
  /// KeepOpen points (passages.h). Its width_at is the import's own, from min_time_step.
  PassageOptions passages;
  /// The time step the mesh must allow (Mesh.MinTimeStep, seconds; 0: off): with
  /// `depth_at`, a passage narrower than min_time_step sqrt(g H) at its place (one element
  /// across it, at Courant number 1) is closed too, and a KeepOpen passage narrower than
  /// that is logged as such (RepairEntry::step).
  double min_time_step = 0;
  /// The water depth (metres, positive down, already raised to the model's minimum) at
  /// a lon/lat; called from the importing thread only.
  std::function<double(geo::LonLat)> depth_at;
  /// Keep only the seas (surfaces) holding one of these points; empty: every sea.
  std::vector<geo::LonLat> sea_at;
  /// Reports stage "coastline" with one unit per pipeline step (levels, cleaning,
  /// clipping, coarsening, curves, repair, surfaces, output: 8); null: silent.
  Progress* progress = nullptr;
};

/// One curve of the model: a whole island (periodic: first point not repeated), a cut
/// coastline piece, or a piece of the region box (open_boundary).
struct CoastCurve {
  std::vector<geo::LonLat> ll;
  std::vector<Vec2> uv;                // unit-scaled PolarSphere parameters of ll
  bool periodic = false;
  bool open_boundary = false;
  std::size_t record = 0;              // source record (-1 for box pieces)
  std::int64_t id = -1;                // source id
};

/// Curves in order, each traversed forward, water on the left: the outer loop of a
/// surface runs counter-clockwise in (u,v), its holes clockwise.
struct CoastLoop {
  std::vector<std::uint32_t> curves;
};

struct CoastSurface {
  std::uint32_t outer;                 // loop index
  std::vector<std::uint32_t> holes;    // loop indices
};

/// One line of the import report with its parts, so that a diagnostic listing many
/// of them can show each briefly (its place and its figure) and count them by sort.
struct ReportLine {
  std::string text;        ///< the whole line ("record 12 (id 345) at lon ... lat ...: what (figure)")
  std::string what;        ///< the sort of change ("strait narrower than the accuracy kept open"); "" for the summaries
  std::string figure;      ///< the figure that matters ("width 1234 m"), or ""
  bool has_place = false;  ///< `where` is the change's place
  geo::LonLat where;
  bool passage = false;    ///< a closed passage, a dam or removed narrow water
  bool sea_dropped = false;  ///< a sea dropped by SeaAt
  bool kept_open = false;    ///< a passage kept open by KeepOpen
  /// A KeepOpen passage narrower than Mesh.MinTimeStep needs: that step cannot be met there.
  bool step_unmet = false;
  /// The figure as a number when its largest matter most (a closed passage's width, a
  /// dropped sea's area): a short list shows the largest first; NaN otherwise.
  double rank = std::numeric_limits<double>::quiet_NaN();
  /// The change the line tells, for the interpreter to word (its `where` as `where` above);
  /// none for the summaries.
  std::optional<RepairEntry> entry = std::nullopt;
};

/// The CPU seconds (every thread) and the wall seconds one step of the import took.
struct ImportStepTime {
  std::string name;
  double seconds = 0;
  double wall = 0;
};

struct ImportReport {
  CleanReport clean;
  std::vector<DroppedRing> dropped;
  std::vector<RepairEntry> repair;
  std::size_t reversed = 0, points_in = 0, points_out = 0, repair_rounds = 0;
  /// How far the curves lie from the source points before and after control points were
  /// put back (deviation.h), in metres.
  DeviationReport deviation;
  /// With a patch: its splice (steps along the patch box where the two sources disagree).
  std::optional<PatchReport> patch;
  /// Each step's CPU seconds in the order the steps first ran (a step run again, as the
  /// repair pass after the straits, adds to its first entry): where the import's time goes.
  std::vector<ImportStepTime> step_cpu;
  std::size_t count(RepairKind k) const;
  /// The human-readable report, nothing cut: the cleaning and coarsening summaries,
  /// then one line per repair entry in `repair`'s order, each with its parts.
  std::vector<ReportLine> items() const;
};

struct CoastModel {
  std::vector<CoastCurve> curves;
  std::vector<CoastLoop> loops;
  std::vector<CoastSurface> surfaces;      // outer loop first in each; ocean first
  std::vector<std::uint32_t> unassigned;   // hole loops with no outer (no Antarctica, no region)
  std::size_t seas_dropped = 0;            // surfaces left out by sea_at (each a DroppedSea entry)
  /// The Region held no shoreline: the model is its box, one loop of open boundary.
  bool region_empty = false;
  ImportReport report;
};

Result<CoastModel> build_coast_model(Coastline data, const ImportOptions& opt);

}  // namespace sm::coast
