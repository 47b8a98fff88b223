// Incremental insertion of a point into a constrained Delaunay triangulation:
// a walk that never crosses constrained edges, then a Bowyer-Watson cavity
// bounded by them. Shared by the refinement algorithms (del2d; frontal and
// meshadapt later).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "base/rng.h"
#include "exact/predicates.h"
#include "mesh/triangulation.h"

namespace sm {

enum class InsertOutcome : std::uint8_t {
  Inserted,
  Outside,     // beyond a constrained or hull edge from the start triangle
  Duplicate,   // equal to a corner of its triangle
  NotVisible,  // the cavity has an edge the point does not see strictly (on a constraint, say)
  Rejected,    // refused by the caller's CavityCheck
};

/// An edge of a cavity's boundary, counter-clockwise around the cavity: the new point
/// would make the triangle (a, b, point).
struct CavityEdge {
  VertexId a, b;
};

/// A caller's last word on an insertion, asked once the cavity is known and before the
/// mesh changes (the frontal mesher's Gmsh rule, frontal.cpp).
class CavityCheck {
 public:
  virtual ~CavityCheck() = default;
  /// False refuses p, whose cavity has `triangles` triangles and is bounded by `boundary`.
  virtual bool accept(Vec2 p, std::size_t triangles, std::span<const CavityEdge> boundary) = 0;
};

struct InsertStats {
  std::uint64_t walk_steps = 0, cavity_triangles = 0;
};

class PointInserter {
 public:
  explicit PointInserter(TriangleStore& m, std::uint64_t seed = 0x2545F4914F6CDD1Dull,
                         PredicateStats* predicate_stats = nullptr)
      : m_(m), st_(predicate_stats), rng_(seed) {}

  /// Visibility walk from the live triangle `hint` towards p that never
  /// crosses a constrained or hull edge (random edge order, fixed seed).
  /// Returns a triangle containing p (closed), or kNone when p lies beyond
  /// such an edge or is not finite.
  TriId locate(Vec2 p, TriId hint);

  /// Inserts p, contained in triangle t: the cavity is the set of triangles
  /// whose circumcircle holds p (ties broken by id), reached without
  /// crossing constrained edges; it is refilled by a fan around p. Side
  /// flags of the cavity boundary are kept; out_side is maintained (see
  /// keep_out_side). The
  /// mesh is unchanged unless the outcome is Inserted; a point that is not
  /// finite is Outside. A `check` that refuses the cavity makes it Rejected.
  InsertOutcome insert(Vec2 p, TriId t, CavityCheck* check = nullptr);

  /// locate() then insert().
  InsertOutcome insert_near(Vec2 p, TriId hint) {
    const TriId t = locate(p, hint);
    return t.valid() ? insert(p, t) : InsertOutcome::Outside;
  }

  /// The vertex made by the last successful insertion.
  VertexId last_vertex() const { return last_; }
  /// The corners of the triangle that contained it (counter-clockwise; still vertices).
  const std::array<VertexId, 3>& last_container() const { return container_; }
  /// Slots of the triangles made by the last successful insertion.
  std::span<const std::uint32_t> created() const { return {cavity_.data(), created_}; }

  InsertStats stats;
  /// When false, out_side is left alone (a scattered write per cavity
  /// vertex): for a caller that inserts many points and then calls
  /// TriangleStore::rebuild_out_side().
  bool keep_out_side = true;

 private:
  struct Bound {
    VertexId a, b;  // first, as in CavityEdge (the boundary handed to a CavityCheck)
    Side outer;
    std::uint8_t flags;
  };
  TriangleStore& m_;
  PredicateStats* st_;
  Rng rng_;
  VertexId last_;
  std::array<VertexId, 3> container_{};
  std::size_t created_ = 0;
  std::vector<std::uint32_t> stack_, cavity_, vmap_, next_;
  std::vector<Bound> bound_;
  std::vector<CavityEdge> edges_;  // bound_'s edges, for a CavityCheck
};

}  // namespace sm
