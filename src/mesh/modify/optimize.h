// Quality optimisation after 2D refinement (paper section 3.3): quality swaps
// and optimisation-based smoothing of the vertices of the worst triangles, in rounds,
// so that the minimum rho of the mesh rises without moving the boundary.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "base/vec.h"
#include "mesh/triangulation.h"

namespace sm {

struct OptimizeOptions {
  /// Rounds of (swaps, then smoothing) over the triangles below `threshold`.
  int rounds = 4;
  /// Triangles with rho below this are worked on; the others only change when a
  /// neighbour's vertex moves (and then never below the worst of the star).
  double threshold = 0.9;
  /// Only a star (or swap pair) whose worst rho is below this may push other
  /// triangles from above 0.9 to below it (and only for a gain of 0.02 in the worst
  /// rho per triangle lost, paid from triangles earlier changes lifted above 0.9, so
  /// the share of rho > 0.9 never ends lower). Raise it to lift the minimum further.
  double sacrifice_below = 0.8;
  /// The share of rho > 0.9 may end this much below the input's (a fraction of the
  /// triangle count; 0: never lower). Sacrifices are otherwise paid only by triangles
  /// that earlier changes lifted above 0.9, which a threshold below 0.9 rarely makes.
  double max_share_loss = 0;
  /// After the rounds, triangles still below this try compound changes: an edge
  /// flipped even if that alone loses, then the quad's corners moved, kept only when
  /// the sorted rho round them rises, the worst not lower and none dropping below 0.9
  /// (undone otherwise).
  double compound_below = 0.85;
  /// Compound changes are tried only on edges whose flip raises sum (valence - 6)^2 over
  /// the quad's free inner corners by at most this (flip_valence.h). Where a size ramp makes
  /// the front drop points (pairs of valence 5 and 7), the flips that pull valences away
  /// from 6 cost a quarter of the compound rounds' time and rarely succeed (docs/benchmarks.md).
  int compound_valence_rise = 2;
  /// Each loop of rounds (swaps and moves, then compound changes) ends after a round that
  /// lifts fewer than this share of its bad triangles to the threshold or above: the later
  /// rounds cost as much as the first and lift far fewer (docs/benchmarks.md). 0: the
  /// loops end only when a round changes nothing (or after `rounds`).
  double min_round_gain = 0.03;
  /// Moves tried per vertex and round (each one a small line search).
  int smooth_iterations = 2;
  /// Measure the star again for a candidate that lands on the vertex's current position
  /// (the old way; the result is the same either way: for the tests' comparison).
  bool remeasure_current = false;
  /// A swap is kept only when the worse rho of its pair rises by more than this (so
  /// swaps cannot cycle). Moves and compound changes compare the sorted qualities
  /// around them worst first (leximin, ties within 1e-3) and never lower the worst.
  double min_gain = 1e-9;
  /// Optional surface map (u,v) -> xyz: rho is then measured on the chord
  /// triangles in space instead of the parameter plane. Validity (no inverted
  /// triangle) is always decided in the plane with the exact orient2d. Leave empty
  /// on conformal parametrisations (plane, PolarSphere, Mercator) where plane rho is
  /// sphere rho to first order.
  std::function<Vec3(Vec2)> to_space;
  /// Threads for the scans over every triangle (the first measure, the last minimum),
  /// without to_space: fixed chunks reduced in chunk order, the same bytes for every
  /// count. The swaps and moves stay serial, unless the store is blocked (below).
  int threads = 1;
  /// A store of at least this many live triangles, without to_space, is optimised in
  /// blocks (optimize_blocks.h; an undo journal on the store is kept): the blocks on the
  /// threads, then a serial pass round their borders. The blocks depend on the mesh only, so the bytes
  /// are the same for every thread count (but not those of the one serial pass). 0: never.
  std::uint32_t block_min_triangles = 200000;
  /// Bad triangles (below threshold) per block: enough that a block's own work dwarfs its
  /// copying, few enough that two threads share a face's blocks evenly. A face with fewer
  /// than twice this many is optimised by the serial pass alone.
  std::uint32_t block_bad = 4096;
  /// When given (one flag per triangle slot), only flagged triangles start the list of
  /// those worked on (the blocked pass's border pass); the others join it only when a
  /// change touches them.
  const std::vector<std::uint8_t>* seeds = nullptr;
};

struct OptimizeStats {
  std::uint64_t swaps = 0, moves = 0;
  std::uint64_t refused = 0;                         // a move failing the exact check
  std::uint64_t star_measures = 0;                   // candidate positions measured (line searches)
  // Compound changes tried (an edge flipped), and of those the ones decided to fail before
  // their moves: a new triangle with its three corners fixed and below the worst rho
  // round the quad before (round a coast edge much shorter than its neighbours, a dam),
  // or the same change failed before with the stars of its corners unchanged since.
  std::uint64_t compound_tried = 0, compound_pinned = 0, compound_repeated = 0;
  std::uint64_t compound_valence_skipped = 0;        // edges left alone by compound_valence_rise
  std::uint32_t bad_before = 0, bad_after = 0;       // triangles below the threshold
  double min_before = 0, min_after = 0;              // worst rho (as measured by the pass)
  int rounds = 0;
  std::uint32_t blocks = 0;                          // optimised in blocks (optimize_blocks.h)
};

/// Raises the worst triangle qualities of a refined triangulation (plane or
/// parametric plane). Vertices [0, fixed_count) and every vertex of a constrained or
/// hull edge stay where they are; constrained edges are never flipped, so every
/// constraint stays present. Each round: (1) the edges of the triangles below the
/// threshold, worst first, are flipped when that raises the worse rho of the two
/// triangles (exact orient2d: the new pair must be counter-clockwise), with cascades
/// to the edges around each flip; (2) each free vertex of those triangles is moved
/// where the sorted rho of its star is better (leximin, the worst never lower):
/// candidates are the mean of its neighbours, the mean of the points that would make
/// each star triangle equilateral on its outer edge, and that point for the worst
/// triangle, each tried with step 1, 1/2, ... 1/128; the best is kept only when every
/// star triangle is counter-clockwise by the exact orient2d. Stops early when a round changes
/// nothing or lifts few (min_round_gain). Then (3) triangles still below compound_below try a
/// flip of each edge whose flip does not pull the valences far from 6 (compound_valence_rise)
/// followed by two sweeps of moves of the quad's corners, undone unless the sorted
/// qualities round them rise. The result is valid but in general no longer Delaunay.
/// Deterministic: triangles are handled by increasing (rho, id), vertices by id.
OptimizeStats optimize_quality(TriangleStore& m, std::uint32_t fixed_count, const OptimizeOptions& opt = {});

/// A triangle below the threshold: its plane rho and its slot, ordered worst first.
struct BadTri {
  double q;
  std::uint32_t t;
  bool operator<(const BadTri& o) const { return q < o.q || (q == o.q && t < o.t); }
};

/// Every live triangle of m measured by its plane rho in fixed chunks on `threads` threads:
/// those below `threshold` (and flagged in `seeds`, when given) appended to `bad` by slot,
/// the lists joined in chunk order, and the lowest rho returned (flat ones as 0). The same
/// for every thread count.
double scan_plane_bad(const TriangleStore& m, double threshold, int threads, const std::vector<std::uint8_t>* seeds,
                      std::vector<BadTri>& bad);

}  // namespace sm
