// Edge split (local mesh modification, Geuzaine & Remacle 2008; paper
// section 3.3, meshadapt): a new vertex on an edge, the one or two triangles
// beside it each cut in two.
#pragma once

#include "exact/predicates.h"
#include "mesh/triangulation.h"

namespace sm {

/// Splits the edge of side s (a -> b) at p, normally its midpoint. Every
/// new triangle must turn counter-clockwise (exact orient2d, counted in st);
/// otherwise nothing changes and the result is kNone. A constrained edge is
/// split only when allow_constrained is set; its two halves keep the edge's
/// flags. Returns the new vertex; on success the triangle slots touched are
/// tri_of(s), tri_of(twin(s)) and the one or two slots added last.
VertexId split_edge(TriangleStore& m, Side s, Vec2 p, bool allow_constrained = false,
                    PredicateStats* st = nullptr);

}  // namespace sm
