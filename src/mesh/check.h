// Invariant checkers for the triangulation store; tests run them after every
// operation. They never abort: a failure is returned with the offending ids.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "mesh/geometry.h"
#include "mesh/triangulation.h"

namespace sm {

struct CheckResult {
  std::string error;  // empty when the invariant holds
  bool ok() const { return error.empty(); }
};

/// Twins symmetric and consistent, corners distinct, every live triangle
/// counter-clockwise (exact orient2d on m.xy), out_side valid, each vertex a
/// single fan (manifold), no edge twice, free list = dead slots.
CheckResult check_topology(const TriangleStore& m);

/// No vertex strictly inside the circumcircle of a neighbouring triangle
/// across a non-constrained edge (locally Delaunay = Delaunay for a
/// triangulation whose constrained edges are honoured). With canonical, the
/// id tie-break must agree too (the unique perturbed triangulation).
CheckResult check_delaunay(const TriangleStore& m, const PlanarGeometry& g, bool canonical = false);

/// Every edge (a, b) is present and flagged kConstrained on both sides.
CheckResult check_constraints(const TriangleStore& m, const std::vector<std::pair<VertexId, VertexId>>& edges);

}  // namespace sm
