// Mesh partitions for MPI ocean models, as Gmsh 4.8.4 makes them (Mesh.NbPartitions,
// -part): METIS on the dual graph of the 2D elements (io/dual_graph.h), the lines and
// points then given the part of an element they bound, so that each part is whole.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/mesh_model.h"

namespace sm::io {

struct MeshPartitionOptions {
  int parts = 2;        ///< Mesh.NbPartitions, >= 1
  int algorithm = 1;    ///< Mesh.MetisAlgorithm: 1 recursive bisection, 2 k-way (Gmsh's numbers)
  int ufactor = -1;     ///< Mesh.MetisMaxLoadImbalance in 1/1000; -1: METIS's (30 k-way, 1 recursive)
};

/// Parts are numbered 1..parts, as Gmsh numbers partitions.
struct MeshPartition {
  int parts = 0;
  std::vector<std::vector<int>> element_part;  ///< per MeshModel entity, per element
  std::vector<std::pair<int, int>> entities;   ///< (dim, tag) of each element_part row
  std::vector<int> node_part;                  ///< per node: the smallest part of an element using it; 0: none
  std::vector<std::uint64_t> part_elements;    ///< 2D elements in each part (index 0 is part 1)
  std::uint64_t edge_cut = 0;                  ///< dual-graph edges between two parts
  double imbalance = 1;                        ///< largest part / the mean (1.03: 3% over)
};

/// Why partition_mesh could not partition (the interpreter words it): no 2D element, more
/// parts than 2D elements (or fewer than 1), METIS out of memory or failing otherwise.
enum class PartitionProblem { None, NoElements, PartCount, MetisOutOfMemory, MetisFailed };

struct PartitionError {
  PartitionProblem problem = PartitionProblem::None;
  std::size_t elements = 0;   ///< PartCount: the 2D elements there are to partition
};

/// Partitions `mesh`; false with *error when it cannot. The answer depends only on the mesh
/// and the options (METIS seeded, the graph in a fixed order), never on threads.
bool partition_mesh(const MeshModel& mesh, const MeshPartitionOptions& opt, MeshPartition* out, PartitionError* error);

/// `partition` with its rows in the order of `mesh`'s entities, matched by (dim, tag): for a
/// MeshModel built from the same mesh but with entities left out or reordered since (a
/// writer's node coordinates drop the points off the sphere). An entity it lacks gets part 1.
MeshPartition aligned_partition(const MeshPartition& partition, const MeshModel& mesh);

}  // namespace sm::io
