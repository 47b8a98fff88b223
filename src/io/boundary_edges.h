// The edges of a mesh's boundary: the curve elements that have a face on one side only
// (an embedded curve inside a face has faces on both and is not boundary), with the curve
// and the physical curve group they lie on. For the UGRID file and the Python module.
#pragma once

#include <cstdint>
#include <vector>

#include "io/mesh_model.h"

namespace sm::io {

struct BoundaryEdge {
  std::uint32_t a = 0, b = 0;   ///< MeshModel nodes, in the curve's direction
  int curve = 0;                ///< the curve entity's tag
  int physical = 0;             ///< its smallest physical group tag, 0 when in none
};

/// In curve tag order, then element order; each edge once.
std::vector<BoundaryEdge> boundary_edges(const MeshModel& mesh);

}  // namespace sm::io
