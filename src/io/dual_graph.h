// The dual graph of a mesh's 2D elements (triangles and quadrangles): one vertex per
// element, an edge between two elements that share a mesh edge, across surfaces too.
// This is the graph METIS partitions (io/mesh_partition.cpp), as Gmsh 4.8.4's
// PartitionMesh does for a 2D mesh.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "io/mesh_model.h"

namespace sm::io {

/// Compressed adjacency (METIS's xadj/adjncy layout): the neighbours of vertex i are
/// adjncy[xadj[i] .. xadj[i+1]), in increasing order.
struct DualGraph {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> elements;  ///< (entity index, element) per vertex
  std::vector<std::int32_t> xadj{0};
  std::vector<std::int32_t> adjncy;
  std::size_t size() const { return elements.size(); }
};

/// The graph over every 2D element of `mesh`, the entities taken in (dim, tag) order and
/// each entity's elements in their order, so the same mesh always gives the same graph.
DualGraph dual_graph_2d(const MeshModel& mesh);

}  // namespace sm::io
