// Geometry seen by the triangulation algorithms: predicates on vertex ids.
// The same PlanarGeometry serves the Euclidean plane and the stereographic
// plane of the sphere (circles map to circles, so Delaunay is preserved).
#pragma once

#include <cstdint>
#include <vector>

#include "base/id.h"
#include "base/vec.h"
#include "exact/predicates.h"

namespace sm {

/// Exact in-circle with ties broken by the ids ia..id (symbolic perturbation
/// of the lifted points, |p|^2 + eps^id: larger ids are lifted more). Never
/// Zero when a, b, c is a proper counter-clockwise triangle and the ids are
/// distinct, so the Delaunay triangulation is unique whatever the insertion
/// order.
Sign incircle_sos_tie(Vec2 a, Vec2 b, Vec2 c, Vec2 d, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                      std::uint32_t id, PredicateStats* st);
inline Sign incircle_sos(Vec2 a, Vec2 b, Vec2 c, Vec2 d, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                         std::uint32_t id, PredicateStats* st = nullptr) {
  const Sign s = incircle(a, b, c, d, st);
  return s != Sign::Zero ? s : incircle_sos_tie(a, b, c, d, ia, ib, ic, id, st);
}

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
  /// In-circle with exact ties broken by vertex id (see incircle_sos).
  Sign in_circle_sos(VertexId a, VertexId b, VertexId c, VertexId d) const {
    return incircle_sos(pos(a), pos(b), pos(c), pos(d), a.value, b.value, c.value, d.value, stats);
  }
};

}  // namespace sm
