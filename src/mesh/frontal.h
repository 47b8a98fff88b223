// Frontal-Delaunay refinement (front2d, Mesh.Algorithm 6; paper
// section 3.3) after Rebay (1993): points are placed on the Voronoi edges of
// the active front so that each new triangle is equilateral at the local size.
#pragma once

#include <cstdint>

#include "mesh/refine.h"
#include "mesh/triangulation.h"

namespace sm {

/// del2d's result plus the frontal algorithm's own counters.
struct FrontalResult : RefineResult {
  std::uint64_t frontal_points = 0;         // points placed by Rebay's rule
  std::uint64_t circumcentre_fallbacks = 0; // frontal point unusable, circumcentre inserted instead
  std::uint64_t given_up = 0;               // neither could be inserted: triangle accepted as resolved
  std::uint64_t gmsh_rejected = 0;          // refused by Gmsh's rule (RefineOptions::gmsh_rejection): left as it is
};

/// Refines a constrained Delaunay triangulation of the domain (outside
/// triangles removed, boundary edges kConstrained) with the same options as
/// refine_del2d, so a face driver can pick either algorithm. A triangle is
/// resolved when its circumradius R <= radius_limit * h, with h the size at
/// its circumcentre (from `size_at` in batches, or `size`). The active front
/// is the unresolved triangles that touch a resolved one or a constrained or
/// hull edge; the active triangle with the largest R / h gets a new point on
/// the perpendicular bisector of its front edge (a, b), at distance
/// rho + sqrt(rho^2 - p^2) from the midpoint, where p = |ab| / 2, q is the
/// distance from the midpoint to the triangle's circumcentre, rho =
/// min(max(h_ab / sqrt 3, p), (p^2 + q^2) / (2 q)) and h_ab the mean size at
/// a and b: the triangle (a, b, point) is equilateral of side h_ab when the
/// edge has that length, and the point never goes past the circumcentre.
/// When that point cannot be used (outside the triangle's circumcircle,
/// beyond a constraint) the circumcentre is tried, as in del2d; when neither
/// can be inserted the triangle is accepted as it is (counted in given_up).
/// Reconnection is Bowyer-Watson (PointInserter), so the result is
/// constrained Delaunay. In the stereographic plane pass size_at = delta /
/// lambda (the map is conformal, so the isotropic criterion holds there).
/// Deterministic. The front is served from refine_del2d's work list and the
/// mesh is renumbered as it grows, as there (vertices present on entry keep
/// their ids).
FrontalResult refine_front2d(TriangleStore& m, const RefineOptions& opt);

}  // namespace sm
