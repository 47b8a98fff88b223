// The boundary of a merged mesh's discrete surface (mesh/discrete_mesh.h) in terms of its
// discrete curves: what `CreateGeometry;` needs to turn a flat discrete surface into a
// plane surface bounded by those curves (Gmsh 4.8.4's discreteFace::createGeometry, which
// for a planar mesh keeps the plane as the parametrisation).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/discrete_mesh.h"

namespace sm {

struct DiscreteSurfaceBoundary {
  enum class Problem {
    None,
    NotPlanar,        // node_a lies `distance` off the plane of the surface's elements
    EdgeOnNoCurve,    // the boundary edge node_a-node_b is on no discrete curve
    CurvePartlyIn,    // `curve` has mesh edges on the boundary and others not
  };
  Problem problem = Problem::None;
  std::uint64_t node_a = 0, node_b = 0;
  int curve = 0;
  double distance = 0;
  /// The boundary's discrete curves by closed chain (connected by their end nodes), the
  /// chain that reaches farthest (the enclosing one) first, each in curve-tag order.
  std::vector<std::vector<int>> loops;
  /// Discrete curves all of whose mesh edges are interior edges of the surface.
  std::vector<int> inner_curves;
};

/// The boundary of discrete surface `surface` of `d` made of the discrete curves `curves`
/// (tags of d.curve_nodes): a boundary edge is an edge of one element only. Planar within
/// 1e-6 of its elements' bounding-box diagonal.
DiscreteSurfaceBoundary discrete_surface_boundary(const DiscreteEntities& d, int surface,
                                                  const std::vector<int>& curves);

}  // namespace sm
