// Edge collapse (local mesh modification, Geuzaine & Remacle 2008; paper
// section 3.3, meshadapt): a vertex removed by merging it onto a neighbour.
#pragma once

#include <cstdint>
#include <vector>

#include "exact/predicates.h"
#include "mesh/triangulation.h"

namespace sm {

/// The sides leaving v in counter-clockwise order round v (for_each_fan_side,
/// triangulation.h): FanEnd::Closed for an inner vertex; FanEnd::Open on the hull,
/// the first side then the clockwise-most one (an isolated vertex: Open, no sides);
/// FanEnd::Corrupt, with out empty, when the twins round v do not form a fan.
FanEnd vertex_ring(const TriangleStore& m, VertexId v, std::vector<Side>& out);

/// Why a collapse was refused.
enum class CollapseCheck : std::uint8_t {
  Ok,
  Constrained,   // v lies on a constrained or hull edge (it would leave the boundary)
  Link,          // v and w share a neighbour other than the two apexes (topology would break)
  Inverted,      // a triangle of v's ball would turn clockwise or flat at w (exact orient2d)
  CorruptFan,    // the twins round v do not form a fan (a corrupt store: refused, not walked)
};

/// Whether the edge of side s (v -> w) can collapse v onto w: v is on no
/// constrained or hull edge, the link condition holds and every triangle of
/// v's ball not holding the edge stays counter-clockwise with v moved to w.
/// `ring` is scratch (v's sides on return).
CollapseCheck can_collapse(const TriangleStore& m, Side s, std::vector<Side>& ring, PredicateStats* st = nullptr);

/// Collapses v = org(s) onto w = dest(s) after can_collapse() said Ok (ring
/// as it left it): the two triangles beside the edge die, v's other
/// triangles take w in its place, and v becomes isolated (out_side kNone).
/// Flags of the two merged edge pairs are or-ed.
void collapse_edge(TriangleStore& m, Side s, const std::vector<Side>& ring);

/// Renumbers vertices from `first` on, dropping isolated ones (order kept,
/// so every id below the first dropped vertex stays). Returns the old ->
/// new map (kNone for dropped vertices).
std::vector<std::uint32_t> drop_isolated_vertices(TriangleStore& m, std::uint32_t first = 0);

}  // namespace sm
