// Constrained Delaunay: recovery of constrained edges by edge swaps
// (Weatherill 1990, Sloan 1993) with detection of crossing constraints (the
// paper's section 3.2 rule), and removal of triangles outside the domain.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/geometry.h"
#include "mesh/triangulation.h"

namespace sm {

using Edge = std::pair<VertexId, VertexId>;
constexpr std::uint32_t kNoEdge = 0xFFFFFFFFu;

/// Recovering edge `edge` would swap away constrained edge `other` (kNone
/// when that edge was constrained before this call): the two edges cross.
struct EdgeCrossing {
  std::uint32_t edge = 0, other = 0;
  VertexId u, w;  // endpoints of the crossed constrained edge
};

/// Vertex v lies exactly on the open segment of `edge`; the edge was
/// recovered as the chain of sub-edges through v.
struct VertexOnEdge {
  std::uint32_t edge = 0;
  VertexId v;
};

struct RecoverStats {
  std::uint64_t flips = 0, delaunay_flips = 0, already_present = 0;
};

struct RecoverResult {
  std::string error;                       // malformed input (bad ids, zero-length edge)
  std::vector<EdgeCrossing> crossings;     // in input order of `edge`
  std::vector<VertexOnEdge> touching;      // in input order of `edge`
  RecoverStats stats;
  bool ok() const { return error.empty(); }
  bool clean() const { return ok() && crossings.empty() && touching.empty(); }
};

/// Makes every edge of `edges` an edge of m, flagged kConstrained, by swaps,
/// then restores the constrained Delaunay property around the swapped
/// region. An edge that would need to swap a constrained edge is not
/// recovered and is reported as a crossing. m must be a triangulation of a
/// convex region (for example the output of delaunay()).
RecoverResult recover_edges(TriangleStore& m, const PlanarGeometry& g, const std::vector<Edge>& edges);

/// A closed boundary loop (last vertex joins the first). Holes are removed.
struct Loop {
  std::vector<VertexId> v;
  bool hole = false;
};

struct DomainResult {
  std::string error;
  std::uint32_t removed = 0;
  bool ok() const { return error.empty(); }
};

/// Deletes the triangles outside the domain bounded by the loops (whose
/// edges must be present). A region reached without crossing a loop edge is
/// inside when its innermost enclosing loop is an outer loop: the interior
/// side of each loop is seeded (inside for outer loops, outside for holes),
/// hull triangles are outside, and a flood fill across non-loop edges
/// labels the rest. Both orientations of the loops are accepted; a loop
/// lying outside every outer loop is harmless. Loop edges get kBoundary |
/// kConstrained. Contradictory loops (a region both inside an outer loop and
/// inside a hole, i.e. overlapping loops) are an error and leave m unchanged.
DomainResult remove_outside(TriangleStore& m, const PlanarGeometry& g, const std::vector<Loop>& loops);

}  // namespace sm
