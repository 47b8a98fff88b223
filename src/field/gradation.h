// Gradation limiting (the peers' most wanted feature: OceanMesh2D's limgrad,
// JIGSAW's MARCHE): h is lowered until |grad h| <= rate on the sphere.
#pragma once

#include "field/lonlat_grid.h"

namespace sm::field {

/// Lowers node values so that |h(u) - h(v)| <= rate * |X(u) - X(v)| for every
/// pair of 8-neighbour nodes of `g` (lon wrapping on a global grid), nodes
/// placed on the sphere of the given radius. The result is the largest grid
/// function below the input with that property: h(v) = min over u of
/// (h0(u) + rate * graph distance(u, v)), computed once by a Dijkstra-style
/// fast march from the smallest sizes outward. All values must be > 0.
void limit_gradation(LonLatGrid& g, double rate, double radius);

}  // namespace sm::field
