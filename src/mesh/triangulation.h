// The flat triangulation store (STYLE section 6): per-side corner and twin,
// per-vertex out_side, flags, a free list of dead triangles, compact().
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "base/id.h"
#include "base/vec.h"

namespace sm {

class StoreUndo;

//            apex          side s = 3t+e runs org -> dest, counter-clockwise;
//            /  \          corner[s] = org(s); twin[s] = the same edge seen
//     prev  /    \  next   from the neighbour (kNone on the hull or beside a
//     org  +------+ dest   removed triangle). next(s) starts at dest(s).
//              s
inline TriId tri_of(Side s) { return TriId{s.value / 3}; }
inline Side side_of(TriId t, std::uint32_t e) { return Side{3 * t.value + e}; }
inline Side next(Side s) { return Side{s.value / 3 * 3 + (s.value + 1) % 3}; }
inline Side prev(Side s) { return Side{s.value / 3 * 3 + (s.value + 2) % 3}; }

/// Per-side flags (both sides of an edge carry the same ones).
enum SideFlag : std::uint8_t { kConstrained = 1, kBoundary = 2 };
/// Per-triangle flags. kMark is scratch: an algorithm that sets it clears it.
enum TriFlag : std::uint8_t { kDead = 1, kQueued = 2, kMark = 4 };

struct TriangleStore {
  /// The undo journal attached to the store, if any (store_undo.h). Not copied with the
  /// store: a copy starts without one, and an assignment keeps the target's.
  struct UndoLink {
    StoreUndo* journal = nullptr;
    UndoLink() = default;
    UndoLink(const UndoLink&) {}
    UndoLink& operator=(const UndoLink&) { return *this; }
  };
  std::vector<Vec2> xy;                  // per vertex (plane or stereographic plane)
  std::vector<Side> out_side;            // per vertex: a side leaving it, kNone if isolated
  std::vector<VertexId> corner;          // per side: origin vertex
  std::vector<Side> twin;                // per side: opposite side
  std::vector<std::uint8_t> side_flags;  // per side: SideFlag bits
  std::vector<std::uint8_t> tri_flags;   // per triangle: TriFlag bits
  std::vector<TriId> free_tris;          // dead slots, reused before growing
  UndoLink undo_link;                    // see UndoLink

  /// Every change of a slot's sides or flags, or of a vertex's point or out_side, first
  /// tells the attached journal (none: nothing to do), so that it can be undone.
  void will_change_tri(TriId t) {
    if (undo_link.journal) save_for_undo(t);
  }
  void will_change_tri_of(Side s) {
    if (undo_link.journal && s.valid()) save_for_undo(tri_of(s));
  }
  void will_change_vertex(VertexId v) {
    if (undo_link.journal) save_for_undo(v);
  }

  std::uint32_t num_vertices() const { return static_cast<std::uint32_t>(xy.size()); }
  /// Triangle slots, dead ones included.
  std::uint32_t num_slots() const { return static_cast<std::uint32_t>(tri_flags.size()); }
  std::uint32_t num_triangles() const { return num_slots() - static_cast<std::uint32_t>(free_tris.size()); }
  bool alive(TriId t) const { return !(tri_flags[t.value] & kDead); }

  VertexId org(Side s) const { return corner[s.value]; }
  VertexId dest(Side s) const { return corner[next(s).value]; }
  VertexId apex(Side s) const { return corner[prev(s).value]; }
  VertexId vertex(TriId t, std::uint32_t e) const { return corner[3 * t.value + e]; }
  Vec2 pos(VertexId v) const { return xy[v.value]; }
  bool constrained(Side s) const { return side_flags[s.value] & kConstrained; }
  /// out_side[v] names a live side leaving v.
  bool out_side_ok(VertexId v) const {
    const Side s = out_side[v.value];
    return s.valid() && s.value < corner.size() && alive(tri_of(s)) && corner[s.value] == v;
  }

  VertexId add_vertex(Vec2 p);
  /// A triangle a, b, c (counter-clockwise) with unlinked sides; reuses a dead slot.
  TriId add_triangle(VertexId a, VertexId b, VertexId c);
  /// Marks t dead, unlinks its neighbours and recycles the slot. out_side of
  /// its corners moves to a neighbour around the corner; after killing
  /// several adjacent triangles call rebuild_out_side() (a corner may keep
  /// live triangles that are no longer reachable from the dead ones).
  void kill_triangle(TriId t);
  /// Sets out_side from the live triangles (one pass, highest side wins).
  void rebuild_out_side();
  /// Makes a and b twins of each other.
  void link(Side a, Side b) {
    will_change_tri_of(a);
    will_change_tri_of(b);
    twin[a.value] = b;
    if (b.valid()) twin[b.value] = a;
  }
  /// Sets flags on a side and on its twin.
  void set_edge_flags(Side s, std::uint8_t f);
  void clear_edge_flags(Side s, std::uint8_t f);

  /// The side running a -> b, or kNone (on the hull only b -> a may exist).
  /// At most num_slots() + 1 steps round a (a fan holds each triangle once): when a
  /// corrupt fan does not end, none, with *overrun set when given.
  Side side_between(VertexId a, VertexId b, bool* overrun = nullptr) const;
  bool has_edge(VertexId a, VertexId b) const { return side_between(a, b).valid() || side_between(b, a).valid(); }

  /// Flips the diagonal of the quad formed by the triangles on both sides of
  /// s (a -> b, apexes c and d): afterwards the edge c - d exists. The caller
  /// checks convexity; flags of the four outer edges follow them. Returns the
  /// side d -> c of the new edge.
  Side flip(Side s);

  /// Renumbers live triangles to 0..n-1 (order kept) and empties the free list.
  void compact();
  /// Renumbers the live triangles to 0..n-1 along a Hilbert curve through
  /// their centroids (the free list empties), and the vertices from
  /// `first_movable` on in the order those triangles first use them (vertices
  /// no live triangle uses keep their order, after them). Long insertion runs
  /// then find neighbours close in memory. Fills new_slot[old] (kNone for a
  /// dead slot) and new_vertex[old]; out_side is rebuilt.
  void sort_spatially(std::uint32_t first_movable, std::vector<std::uint32_t>& new_slot,
                      std::vector<std::uint32_t>& new_vertex);
  void clear();
  void reserve(std::uint32_t vertices, std::uint32_t triangles);

 private:
  void save_for_undo(TriId t);
  void save_for_undo(VertexId v);
};

/// How a walk round a vertex's fan (for_each_fan_side) ended.
enum class FanEnd : std::uint8_t {
  Closed,   // back at the first side: the vertex is inside the triangulation
  Open,     // a hull edge (or a removed neighbour) reached both ways round
  Stopped,  // the caller's function asked to stop
  Corrupt,  // more steps than the store has triangle slots: the twins do not form a fan
};

/// Calls fn(s) for each side s leaving v = org(start), start a side of a live triangle:
/// counter-clockwise from start until back at start or at a hull edge, then, for an open
/// fan, clockwise from start (the sides before it, nearest first) to the other hull edge.
/// fn returns void, or bool (false stops the walk: FanEnd::Stopped). A fan holds each
/// triangle once, so the walk takes at most num_slots() steps; a longer one is a corrupt
/// store and stops as FanEnd::Corrupt, which the caller reports or refuses.
template <class Fn>
FanEnd for_each_fan_side(const TriangleStore& m, Side start, Fn&& fn) {
  const auto visit = [&fn](Side s) {
    if constexpr (std::is_void_v<std::invoke_result_t<Fn&, Side>>) {
      fn(s);
      return true;
    } else {
      return static_cast<bool>(fn(s));
    }
  };
  const std::uint32_t slots = m.num_slots();
  std::uint32_t used = slots + 1;  // triangles met counter-clockwise, once the hull is reached
  // Counter-clockwise: twin(prev(s)) leaves v in the next triangle.
  Side s = start;
  for (std::uint32_t k = 0; k < slots; ++k) {
    if (!visit(s)) return FanEnd::Stopped;
    const Side n = m.twin[prev(s).value];
    if (n == start) return FanEnd::Closed;
    if (!n.valid()) {
      used = k + 1;
      break;
    }
    s = n;
  }
  if (used > slots) return FanEnd::Corrupt;
  // Clockwise from the start: next(twin(s)) leaves v in the previous triangle.
  s = start;
  for (std::uint32_t k = used; k <= slots; ++k) {
    const Side o = m.twin[s.value];
    if (!o.valid()) return FanEnd::Open;
    if (k == slots) break;
    s = next(o);
    if (!visit(s)) return FanEnd::Stopped;
  }
  return FanEnd::Corrupt;
}

/// A store from vertex positions and counter-clockwise triangles; twins are
/// found by matching opposite sides. Returns false (store left empty) when
/// an edge is used twice in the same direction or an id is out of range.
bool build_triangulation(std::vector<Vec2> xy, const std::vector<std::array<std::uint32_t, 3>>& tris,
                         TriangleStore& out);

}  // namespace sm
