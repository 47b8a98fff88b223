// `Compound Curve{...};` (Gmsh 4.8.4's compound meshing constraint, Geo/GEdge.cpp's
// meshCompound): the curves are meshed as one curve, their nodes spread along the
// concatenation by the size field as if the inner end points were not there. Gmsh meshes
// a discrete curve through them and writes it as a curve of its own; here every mesh
// edge stays on the original curve it lies on, so each inner end point keeps a node: the
// concatenation's node nearest to it is moved onto it (the count stays Gmsh's), or, when
// that node is an end or already moved, the end point is one node more. Gmsh's discrete
// curve takes at least 2 segments (3 when closed), a compound of one curve too.
#pragma once

#include <vector>

#include "geo/model.h"

namespace sm {

/// One curve of a chained compound, in the chain's direction.
struct CompoundLink {
  int curve = 0;
  bool reversed = false;   // the chain runs from the curve's end to its begin
};

/// The curves as one chain, from one end to the other (or round a closed loop, from the
/// first curve's begin): empty when they are not one chain (a missing or repeated curve,
/// a gap, three curves at a point).
std::vector<CompoundLink> chain_compound(const geo::Model& model, const std::vector<int>& curves);

/// The nodes of a chain whose links have size integrals `totals` (in elements, each in
/// the chain's direction): Gmsh's node count for the whole, max(min_segments + 1,
/// floor(A + 1.99)) with A the sum, placed at equal increments of A, then shared out.
/// For each link, the positions of its interior nodes along its own integral (from 0 to
/// its total, increasing in the chain's direction).
std::vector<std::vector<double>> compound_node_positions(const std::vector<double>& totals, int min_segments = 1);

}  // namespace sm
