// Closing narrow passages of water (MinChannelWidth) and dams given by hand (Dams) on the
// repaired, oriented coastline loops, before the B-splines are made. A closure is a
// "2-opt" of two facing coast segments a0->a1 and b0->b1 across the water:
//
//      a1 <------- a0          the segments are replaced by the two dams a0->b1 and
//       |  water   :           b0->a1; the quad a0 a1 b0 b1 between them becomes land.
//       v  (quad)  :           Two loops (island and mainland) become one; one loop
//      b0 -------> b1          (two sides of a canal or an inlet) becomes two seas.
//
// The piece of water a cut separates is dropped when it is all narrow (mean width 2A/P
// below the width), so repeating the cut at the narrowest place left fills a canal or a
// dead-end inlet up to its mouths. Every left/right decision is an exact orient2d.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "coast/coastline.h"
#include "coast/repair_entry.h"
#include "coast/repair.h"

namespace sm::coast {

/// A KeepOpen point's passage: its two banks (the nearest coast on each side of the point)
/// followed along the coast while within kKeepOpenReach x D of the point or within
/// kKeepOpenAcross x D of the other bank, D = max(the closing width there (min_width, or
/// width_at when set), the passage's width there).
inline constexpr double kKeepOpenReach = 3.0;
inline constexpr double kKeepOpenAcross = 2.0;

struct PassageOptions {
  /// Passages narrower than this (metres on the sphere) are closed; 0: none. A passage
  /// exactly this wide stays open (widths are compared within a relative 1e-9).
  double min_width = 0;
  /// Only cuts that drop narrow water (a dead end filled): none that joins two loops or
  /// leaves two waters.
  bool keep_passages = false;
  /// Dams by hand: segments between two lon/lat points, each closing the water it crosses.
  std::vector<std::pair<geo::LonLat, geo::LonLat>> dams;
  /// Points in passages that stay open: no closure joins the two banks of the passage
  /// at such a point (kKeepOpenReach), and a dam across them is an error (option "KeepOpen").
  std::vector<geo::LonLat> keep_open;
  double radius = geo::kEarthRadius;
  /// Threads for the closing rounds' searches (<= 0: the hardware concurrency); the result
  /// is the same for every count.
  int threads = 1;
  /// When set, the width (metres) below which a passage at a place is closed, in place of
  /// min_width there; min_width must bound it from above (it is the search radius).
  std::function<double(geo::LonLat)> width_at;
};

/// What a close_passages call did, counted so that tests can check that its work grows with
/// the coast's size and not with cuts x ring size.
struct PassageStats {
  std::size_t cuts = 0;          // 2-opt moves made (closures, dead ends tried not counted)
  std::size_t node_visits = 0;   // loop points read or linked one by one (all points, kept or not)
  std::size_t kept_visits = 0;   // kept points copied or indexed by cuts, dead-end tests and follows
  // Closing rounds keep what did not change since the round before (passages.cpp, close_round):
  std::size_t polygons_made = 0;   // round-start polygons and widths made (a loop new or changed)
  std::size_t polygons_kept = 0;   // those taken from the round before (the loop unchanged)
  std::size_t near_searched = 0;   // segments searched for near misses (new since the round before)
  std::size_t near_kept = 0;       // near pairs taken from the round before (both segments unchanged)
  std::size_t across_kept = 0;     // of the rounds' near pairs, those whose way across was measured before
  // Water loops' mean widths asked (passages.cpp, fate_of), and of them those read round
  // the ring (the rope's sums not certain, or the width logged; coast/mean_width.h):
  std::size_t width_tests = 0;
  std::size_t width_passes = 0;
};

/// Closes passages and places dams in place (new loops appended, replaced loops marked
/// dead, dams appended as two-point curves). Loops must be intersection-free and oriented
/// water on the left. Appends ClosedPassage / DamPlaced / NarrowWater entries to `log`.
/// Returns whether anything changed; errors (option "Dams"): a dam crossing no water, or
/// one whose ends cannot be joined across the water without crossing a coast; (option
/// "KeepOpen"): a KeepOpen point on land or with no coast across, or a dam closing its
/// passage. Each KeepOpen point is logged as KeptOpen (its place, the passage's width).
Result<bool> close_passages(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops,
                            const PassageOptions& opt, std::vector<RepairEntry>& log,
                            PassageStats* stats = nullptr);

/// Distance in metres on the sphere of `radius` between the (u,v) point p and the closest
/// point of the (u,v) segment a-b (measured as the chord between their points on the sphere).
double uv_point_segment_metres(Vec2 p, Vec2 a, Vec2 b, double radius);

}  // namespace sm::coast
