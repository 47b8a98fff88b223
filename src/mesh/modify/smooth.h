// Laplacian smoothing of the free vertices followed by Delaunay flips (the
// Mesh.Smoothing passes Gmsh applies after 2D meshing).
#pragma once

#include <cstdint>
#include <span>

#include "mesh/triangulation.h"

namespace sm {

struct SmoothStats {
  std::uint64_t moved = 0, refused = 0, flips = 0;
};

/// `passes` times: move every vertex that is on no constrained or hull edge, and is not
/// one of the first `pinned` vertices (a face's embedded points lie on no constrained
/// edge but must stay), to the average of its neighbours, unless that would invert a triangle of
/// its fan (exact orient2d at the new place); then flip non-constrained
/// edges until the mesh is constrained Delaunay again (id tie-break). The averaging and
/// the inversion checks run on `threads` threads, and so do the flips' first in-circle
/// tests (<= 1: the calling thread only; the flips themselves stay serial); the result is
/// the same bytes for any thread count.
SmoothStats smooth_laplacian(TriangleStore& m, int passes, int threads = 1, std::uint32_t pinned = 0);

/// Lawson flips over every non-constrained edge until all are locally
/// Delaunay. Returns the number of flips. With threads > 1 every edge is first tested
/// in parallel and the serial flips test anew only edges a flip has changed: the same
/// flips in the same order, the same bytes for any thread count.
std::uint64_t make_delaunay(TriangleStore& m, int threads = 1);

/// The same flips, starting from the edges of the alive triangles `tris` only (and
/// cascading from there): after a local change (a point inserted, an edge split) that
/// left the rest of the mesh as it was. Returns the number of flips.
std::uint64_t make_delaunay_around(TriangleStore& m, std::span<const TriId> tris);

}  // namespace sm
