// Geometry seen by the triangulation algorithms: predicates on vertex ids.
// The same PlanarGeometry serves the Euclidean plane and the stereographic
// plane of the sphere (circles map to circles, so Delaunay is preserved).
#pragma once

#include <utility>
#include <vector>

#include "base/id.h"
#include "base/vec.h"
#include "mesh/predicates.h"

namespace sm {

struct PlanarGeometry {
  const std::vector<Vec2>* xy = nullptr;
  PredicateStats* stats = nullptr;  // optional counters

  Vec2 pos(VertexId v) const { return (*xy)[v.value]; }
  Sign orient(VertexId a, VertexId b, VertexId c) const { return orient2d(pos(a), pos(b), pos(c), stats); }
  /// Exact in-circle: Positive when d is strictly inside the circle of the
  /// counter-clockwise a, b, c; Zero when cocircular.
  Sign in_circle(VertexId a, VertexId b, VertexId c, VertexId d) const {
    return incircle(pos(a), pos(b), pos(c), pos(d), stats);
  }
  /// In-circle with exact ties broken by vertex id (symbolic perturbation of
  /// the lifted points, |p|^2 + eps^id: larger ids are lifted more). Never
  /// Zero when a, b, c is a proper counter-clockwise triangle, so the
  /// Delaunay triangulation is unique whatever the insertion order.
  Sign in_circle_sos(VertexId a, VertexId b, VertexId c, VertexId d) const {
    const Sign s = in_circle(a, b, c, d);
    return s != Sign::Zero ? s : in_circle_tie(a, b, c, d);
  }

 private:
  Sign in_circle_tie(VertexId a, VertexId b, VertexId c, VertexId d) const {
    // det of rows (x, y, w, 1) is linear in w: the coefficient of the lift of
    // a is +orient(b,c,d), of b -orient(a,c,d), of c +orient(a,b,d), of d
    // -orient(a,b,c). The point with the largest id dominates; a perturbation
    // that lifts a point more pushes it outside, hence the signs below.
    const VertexId v[4] = {a, b, c, d};
    int order[4] = {0, 1, 2, 3};
    for (int i = 1; i < 4; ++i)
      for (int j = i; j > 0 && v[order[j]].value > v[order[j - 1]].value; --j) std::swap(order[j], order[j - 1]);
    for (int k : order) {
      Sign s;
      switch (k) {
        case 0: s = orient(b, c, d); break;
        case 1: s = -orient(a, c, d); break;
        case 2: s = orient(a, b, d); break;
        default: s = -orient(a, b, c); break;
      }
      if (s != Sign::Zero) return s;
    }
    return Sign::Zero;
  }
};

}  // namespace sm
