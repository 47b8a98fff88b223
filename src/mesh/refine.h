// Delaunay refinement (del2d, paper section 3.3) in a plane:
// repeatedly insert the circumcentre of the triangle with the largest
// circumradius over target size, reconnecting by Bowyer-Watson cavities that
// never cross constrained edges, until every triangle is below the bound.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "exact/predicates.h"
#include "mesh/triangulation.h"

namespace sm {

struct RefineOptions {
  double size = 0.1;                     // uniform target edge length
  /// Optional size field, evaluated in batches (STYLE 8: one call, many
  /// points): h[i] = size at pts[i]. Overrides `size`. Called with the
  /// circumcentres of the triangles an insertion creates.
  std::function<void(std::span<const Vec2> pts, std::span<double> h)> size_at;
  /// Optional second size, carried by the vertices as Gmsh 4.8.4's 2D Delaunay and frontal
  /// refiners carry the boundary sizes extended into the face (docs/kernel.md): evaluated at the vertices present on
  /// entry (h[i] at pts[i], inf where none); a vertex inserted later gets the barycentric interpolation of the sizes of
  /// the triangle that contained it, in the mesh being refined; a triangle's size is the smaller of size_at at its
  /// circumcentre and the mean of its vertices' sizes. As the mesh grows, large boundary sizes so reach further in than
  /// an interpolation in the boundary triangulation would let them.
  std::function<void(std::span<const Vec2> pts, std::span<double> h)> vertex_size_at;
  /// With vertex_size_at: h[i] = the factor from its sizes to plane sizes at pts[i] (1 /
  /// the conformal factor of a sphere's plane), applied where a triangle or a vertex is
  /// sized, so the vertices carry sizes on the surface (a plane size, not linear in the
  /// plane, would be interpolated too large). Null: 1.
  std::function<void(std::span<const Vec2> pts, std::span<double> h)> vertex_size_scale;
  /// A triangle is refined while circumradius / size exceeds this. For an
  /// equilateral triangle of side h, R / h = 1/sqrt(3) ~ 0.577.
  double radius_limit = 0.7071067811865476;
  /// front2d only: Gmsh 4.8.4's rule for a new point (docs/kernel.md, Frontal-Delaunay):
  /// refused when it would make a triangle (a, b, point) on its cavity's boundary with the
  /// point closer than 0.5 L to a or b, closer than 0.4 L to the line ab when a and b were
  /// both present on entry (boundary nodes), or an angle at the point above acos(-0.9999),
  /// L the mean size of a, b and the point; or when its cavity is one triangle. The
  /// triangle it was for is then left as it is, and its neighbours do not count it resolved.
  /// For flat (Gmsh) models: it gives Gmsh's triangle counts.
  bool gmsh_rejection = false;
  std::uint32_t max_vertices = 0xFFFFFFF0u;
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;  // walk edge order
  /// Called every `progress_every` insertions with the live triangle count, on the
  /// refining thread (for a progress display; must not touch the mesh). Null: never.
  std::function<void(std::uint64_t triangles)> on_progress;
  std::uint64_t progress_every = 65536;
};

struct RefineStats {
  std::uint64_t inserted = 0;
  std::uint64_t rejected = 0;   // circumcentre outside the domain, on a constraint or not visible
  std::uint64_t pops = 0, stale = 0, walk_steps = 0, cavity_triangles = 0;
  std::uint64_t size_samples = 0;  // points passed to size_at (or given the uniform size)
  PredicateStats predicates;
};

struct RefineResult {
  std::string error;
  RefineStats stats;
  bool ok() const { return error.empty(); }
};

/// Refines a constrained Delaunay triangulation of the domain (outside
/// triangles already removed, boundary edges kConstrained). Constrained
/// edges are never split or crossed; circumcentres beyond them are skipped.
/// The triangle served next is one of the largest R / h (to within a factor
/// 2^(1/64)), the one queued last among those. Deterministic: the order
/// depends only on the input and the options. As the mesh grows, triangle
/// slots and the vertices it adds are renumbered along a Hilbert curve
/// (TriangleStore::sort_spatially); vertices present on entry keep their
/// ids, and the free list ends up empty.
RefineResult refine_del2d(TriangleStore& m, const RefineOptions& opt);

}  // namespace sm
