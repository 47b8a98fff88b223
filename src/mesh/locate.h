// Point location in a triangulation: the one walk of mesh/ (Delaunay construction,
// constrained insertion, the boundary-size interpolation of a face, the quality floor's
// straight walk towards a point it would insert) and the barycentric weights of the point
// in the triangle found.
//
// The walk stands in a triangle and looks at its three sides in rotation order from a
// side its caller chooses (random, or turning, so that it cannot cycle forever on a
// triangulation that is not Delaunay); the first side that has the point strictly on its
// right (exact orient2d) is crossed, unless the caller says the side is a wall (the walk
// stops: Blocked), a side to pass over (the next side is tried) or an entrance where the
// walk ends (a ghost triangle beyond the hull). A triangle with no such side contains
// the point (closed). The walk is bounded by construction: at most `max_steps` crossings
// (the callers pass their triangle count: a visibility walk in a Delaunay triangulation
// enters no triangle twice), then StepLimit, on which each caller scans its triangles.
#pragma once

#include <array>
#include <cstdint>

#include "base/vec.h"
#include "exact/predicates.h"
#include "mesh/triangulation.h"

namespace sm {

/// What lies across a side the walk wants to cross.
enum class Across : std::uint8_t {
  Enter,          // the triangle `next`: the walk goes on there
  EnterAndStop,   // the triangle `next`, where the walk ends (Found)
  Wall,           // nothing the walk may enter: it ends here (Blocked)
  PassOver,       // try the next side in rotation order
};

struct AcrossStep {
  Across kind;
  std::uint32_t next = 0;
};

enum class WalkEnd : std::uint8_t { Found, Blocked, StepLimit };

struct WalkResult {
  std::uint32_t tri;     // where the walk ended
  WalkEnd end;
  std::uint64_t steps;   // triangles crossed into
};

/// The walk of a `Walker` w, which provides
///   std::uint32_t first_side(std::uint32_t t, std::uint64_t step)  side to look at first
///   bool skip(std::uint32_t e)                                      side not to look at
///   Vec2 org(std::uint32_t t, std::uint32_t e), dest(t, e)          ends of side e of t
///   AcrossStep across(std::uint32_t t, std::uint32_t e)             what lies across
///   PredicateStats* predicate_stats()
/// from triangle t towards p, at most max_steps crossings.
template <class Walker>
inline WalkResult walk_to(Walker& w, Vec2 p, std::uint32_t t, std::uint64_t max_steps) {
  for (std::uint64_t steps = 0; steps < max_steps; ++steps) {
    std::uint32_t e = w.first_side(t, steps);
    bool crossed = false;
    for (std::uint32_t k = 0; k < 3 && !crossed; ++k, e = e == 2 ? 0 : e + 1) {
      if (w.skip(e)) continue;
      if (orient2d(w.org(t, e), w.dest(t, e), p, w.predicate_stats()) != Sign::Negative) continue;
      const AcrossStep a = w.across(t, e);
      switch (a.kind) {
        case Across::Enter: t = a.next, crossed = true; break;
        case Across::EnterAndStop: return {a.next, WalkEnd::Found, steps + 1};
        case Across::Wall: return {t, WalkEnd::Blocked, steps};
        case Across::PassOver: break;
      }
      if (crossed) break;
    }
    if (!crossed) return {t, WalkEnd::Found, steps};
  }
  return {t, WalkEnd::StepLimit, max_steps};
}

/// Whether triangle t of the walker holds p (closed): no side has p strictly on its right.
template <class Walker>
inline bool walker_contains(Walker& w, std::uint32_t t, Vec2 p) {
  for (std::uint32_t e = 0; e < 3; ++e)
    if (orient2d(w.org(t, e), w.dest(t, e), p, w.predicate_stats()) == Sign::Negative) return false;
  return true;
}

/// The walk in a TriangleStore: sides are walls when `wall` says so (hull sides, whose
/// twin is kNone, always are, unless pass_over_hull, which passes over them so that the
/// walk ends in the hull triangle nearest the point), the first side looked at from `turn`.
struct StoreWalker {
  const TriangleStore& m;
  PredicateStats* stats = nullptr;
  bool constraints_are_walls = true;
  bool pass_over_hull = false;

  Vec2 org(std::uint32_t t, std::uint32_t e) const { return m.pos(m.org(Side{3 * t + e})); }
  Vec2 dest(std::uint32_t t, std::uint32_t e) const { return m.pos(m.dest(Side{3 * t + e})); }
  bool skip(std::uint32_t) const { return false; }
  PredicateStats* predicate_stats() const { return stats; }
  AcrossStep across(std::uint32_t t, std::uint32_t e) const {
    const Side s{3 * t + e};
    const Side o = m.twin[s.value];
    if (!o.valid()) return {pass_over_hull ? Across::PassOver : Across::Wall};
    if (constraints_are_walls && m.constrained(s)) return {Across::Wall};
    return {Across::Enter, o.value / 3};
  }
};

/// The straight walk of a TriangleStore from g towards p (the quality floor's question:
/// what lies between a triangle and a point it would insert). Of the sides with p
/// strictly beyond, the walk crosses the one the segment g -> p leaves by: in a
/// counter-clockwise triangle its origin lies right of the line g -> p and its destination
/// not right of it (a vertex on the line counts on its left only), never back over the
/// side it came in by; constrained and hull sides are walls, and `wall` is the one the
/// walk stopped at. A line meets a convex triangle in one segment, so a straight walk
/// enters each triangle once: the caller's step limit is its triangle count, and
/// StepLimit means a corrupt triangulation.
struct SegmentWalker {
  const TriangleStore& m;
  Vec2 g, p;
  Side wall{};
  std::uint32_t came_in_by = 3;   // side of the current triangle the walk entered by; 3: none

  Vec2 org(std::uint32_t t, std::uint32_t e) const { return m.pos(m.org(Side{3 * t + e})); }
  Vec2 dest(std::uint32_t t, std::uint32_t e) const { return m.pos(m.dest(Side{3 * t + e})); }
  std::uint32_t first_side(std::uint32_t, std::uint64_t) const { return 0; }
  bool skip(std::uint32_t e) const { return e == came_in_by; }
  PredicateStats* predicate_stats() const { return nullptr; }
  AcrossStep across(std::uint32_t t, std::uint32_t e) {
    const Sign sa = orient2d(g, p, org(t, e)), sb = orient2d(g, p, dest(t, e));
    if (sa != Sign::Negative || sb == Sign::Negative) return {Across::PassOver};
    const Side s{3 * t + e};
    const Side o = m.twin[s.value];
    if (!o.valid() || m.constrained(s)) {
      wall = s;
      return {Across::Wall};
    }
    came_in_by = o.value % 3;
    return {Across::Enter, o.value / 3};
  }
};

/// Fallback of a StoreWalker walk that reached its step limit: the first live triangle
/// that holds p among those reached from `from` without crossing a wall (breadth first,
/// each once), or kNone.
TriId scan_for(const StoreWalker& w, Vec2 p, TriId from);

/// Barycentric weights of p in triangle a, b, c (inexact: for interpolation only; all
/// 1/3 when a, b, c do not turn counter-clockwise in floating point).
std::array<double, 3> barycentric(Vec2 a, Vec2 b, Vec2 c, Vec2 p);

}  // namespace sm
