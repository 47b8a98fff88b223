// How a flip changes the valences round an edge: the cheap test that tells the quality
// pass's compound changes (optimize.cpp) which flips are worth their moves.
#pragma once

#include <cstdint>

#include "mesh/triangulation.h"

namespace sm {

/// The number of triangles round v when v is a free inner vertex (not below fixed_count,
/// its fan closed, none of its edges constrained); -1 otherwise (its best valence then
/// depends on its boundary angle, so it is left out of flip_valence_rise).
int free_valence(const TriangleStore& m, VertexId v, std::uint32_t fixed_count);

/// The rise of sum (valence - 6)^2 over the free inner corners of the quad round s if s
/// were flipped (its ends lose a triangle, the two apexes gain one): negative when the
/// flip brings the valences towards 6 (a 7 next to a 5 made two 6s: -4). s must have a twin.
int flip_valence_rise(const TriangleStore& m, Side s, std::uint32_t fixed_count);

}  // namespace sm
