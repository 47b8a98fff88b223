// The quality floor (Mesh.QualityFloor): after a face is refined and optimised, every
// triangle below rho = q (measured in space: exact/quality.h) is worked on in
// bounded rounds, after Ruppert's refinement: a curve edge is split at a point of its
// curve (the parameter midpoint, or a quarter from an end where the midpoint would turn a
// triangle over; the face tells where: the geometry does not change and faces meshed
// later see the same node), an interior triangle gets its circumcentre inserted (Delaunay
// insertion, exact predicates) unless that point lies beyond a curve edge seen from the
// triangle or inside the diametral circle of one nearby, which is then split instead.
// A triangle alone in a corner's wedge gets legs of equal length (its longer curve edge cut
// at the shorter one's length from the corner); a curve point beyond the far side of the
// triangle on its edge (the curve bending into the face) is reached by flipping that side
// first. Triangles at a corner where the input curves meet at an angle too sharp for q are
// left alone and reported.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "mesh/triangulation.h"

namespace sm {

struct QualityFloorOptions {
  double floor = 0.3;   ///< q: work on triangles with rho < q; <= 0: do nothing
  /// Rounds over the triangles still below q (each round handles every one once). A
  /// narrow inlet's coast takes a round per halving of its edges down to its width.
  int max_rounds = 40;
  /// Points (curve splits and interior points) a face may get; 0: 16 per triangle
  /// below q at the start, plus 256.
  std::uint32_t max_points = 0;
  /// Operations (changes tried: improve, split and insert attempts) the floor may spend;
  /// 0: 64 per triangle below q at the start plus 64 per round of max_rounds plus 1024.
  /// Each operation is local (its walks bounded), so the whole floor is bounded.
  std::uint64_t max_work = 0;
  /// A change may leave triangles worse than the one worked on (the next rounds mend
  /// them); with this set, never below half of its rho nor the worst one at the start.
  bool never_below_start = false;
  /// Threads for the scans over the whole face (every triangle measured each round, every
  /// vertex mapped to space): cut into chunks of a fixed size and reduced in chunk order,
  /// so the result is the same bytes for every count. The changes themselves stay serial.
  int threads = 1;
};

/// What the floor needs from the face it works on (the 2D mesher's face).
struct FloorFace {
  /// The point in space of a vertex: its mesh node, or its plane point mapped to space.
  std::function<Vec3(VertexId)> space;
  /// The point in space of a plane point (to judge a change before making it).
  std::function<Vec3(Vec2)> to_space;
  /// The plane point of the curve point at fraction f (in the curve's parameter) from a
  /// to b, the ends of the constrained edge a - b; none when the edge is not a curve edge
  /// (or its curve may not change).
  std::function<std::optional<Vec2>(VertexId a, VertexId b, double f)> curve_point;
  /// That split was made in the triangulation: v (at the point curve_point gave last)
  /// now lies between a and b.
  std::function<void(VertexId a, VertexId b, VertexId v)> curve_split_done;
  /// Whether v is a model vertex's node, where input curves may meet at a corner.
  std::function<bool(VertexId)> is_corner;
};

/// A corner of the face (a model vertex) whose angle between the constrained edges is
/// too sharp for the floor: a triangle there has that corner's angle or less, so rho <=
/// the rho of the isoceles triangle with that apex.
struct SharpCorner {
  VertexId v;
  double degrees = 0;
};

struct QualityFloorResult {
  std::uint32_t below_before = 0;   ///< triangles with rho < q at the start
  std::uint32_t below_after = 0;    ///< at the end, those at sharp corners included
  std::uint32_t at_sharp = 0;       ///< of below_after: those at a sharp corner
  std::uint32_t rounds = 0, curve_splits = 0, interior_points = 0;
  bool out_of_budget = false;       ///< stopped by max_rounds, max_points or max_work with work left
  bool out_of_work = false;         ///< of out_of_budget: max_work was reached
  std::uint64_t work = 0, work_budget = 0;   ///< operations spent, and allowed
  /// The lowest rho at the start (1 when none is lower), as count_below measures it: a
  /// count-only run (max_rounds 0) gives the face's worst without another scan.
  double worst_before = 1;
  /// An internal error (a walk round a vertex or through the face that did not end within
  /// the store's size: the triangulation is not consistent there): what, and the vertex
  /// near which it happened. The floor stops at once; the caller should put the face back
  /// as it was before the floor and report it.
  std::string fault;
  VertexId fault_at;
  std::vector<SharpCorner> sharp;   ///< distinct corners, by vertex id
  bool changed() const { return curve_splits + interior_points > 0; }
};

/// The smallest apex angle (radians) of an isoceles triangle with rho >= q: below it no
/// triangle with an angle that small reaches q (rho = 8 sin(A/2) sin(B/2) sin(C/2)).
double sharp_angle_limit(double q);

/// Raises the triangles of `m` (a face's refined triangulation, constrained edges its
/// curves) to rho >= opt.floor where it can, as described at the top of this file.
/// Vertices keep their ids; new ones are appended. Deterministic: triangles are handled
/// by increasing (rho, slot), one at a time. Constrained edges stay (split into two).
QualityFloorResult raise_quality_floor(TriangleStore& m, const FloorFace& face, const QualityFloorOptions& opt);

/// Triangles of `m` with rho < q measured by `space`, and the worst rho (1 when none).
/// `space` is called from up to `threads` threads (each vertex once); the result does not
/// depend on the thread count.
std::uint32_t count_below(const TriangleStore& m, const std::function<Vec3(VertexId)>& space, double q,
                          double* worst = nullptr, int threads = 1);

/// The live triangle of `m` with the lowest rho measured by `space`, the smallest slot
/// among equals, and that rho (none and 2 when `m` has no triangle). `space` is called
/// from up to `threads` threads; the answer does not depend on the thread count.
std::pair<TriId, double> worst_triangle(const TriangleStore& m, const std::function<Vec3(VertexId)>& space,
                                        int threads = 1);

}  // namespace sm
