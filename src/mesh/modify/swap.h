// Edge swap for quality (local mesh modification, Geuzaine & Remacle 2008;
// paper section 3.3, meshadapt): the diagonal of a convex quad is flipped
// when that raises the worse quality of its two triangles.
#pragma once

#include <cmath>
#include <cstdint>

#include "exact/predicates.h"
#include "exact/quality.h"
#include "mesh/triangulation.h"

namespace sm {

/// The gain in min(rho) of the two triangles beside s if its diagonal were
/// flipped, or a negative value when it may not be: s constrained or on the
/// hull, or the quad not strictly convex (exact orient2d). rho is measured
/// in the plane (the stereographic plane is conformal, so angles and rho
/// are those of the sphere up to the size of a triangle).
double swap_gain(const TriangleStore& m, Side s, PredicateStats* st = nullptr);

struct SwapStats {
  std::uint64_t swaps = 0, tested = 0;
};

/// Swaps every edge whose swap_gain exceeds min_gain (a relative margin, so
/// no pair of triangles can swap back and forth), then the edges around
/// each swap again, until none is left or max_swaps were made.
/// Deterministic: edges are visited in side order, then as a stack.
SwapStats swap_for_quality(TriangleStore& m, double min_gain = 1e-6, std::uint64_t max_swaps = ~0ull,
                           PredicateStats* st = nullptr);

}  // namespace sm
