// The partitioned entities of a mesh, as Gmsh 4.8.4 builds them with
// Mesh.PartitionCreateTopology = 1 (its Mesh/meshPartition.cpp) for MSH 4.1's
// $PartitionedEntities: each model entity split into one entity per part, the curves
// between two parts, and the points where such curves meet.
#pragma once

#include "io/mesh_model.h"
#include "io/mesh_partition.h"

namespace sm::io {

/// `mesh` with, after its own entities (kept without their elements), the partitioned
/// entities holding every element:
///  - a piece of each model entity per part with elements of it: parent (dim, tag) the
///    entity, partitions {p}, the entity's physical groups (Gmsh's default
///    Mesh.PartitionOldStyleMsh2 = 1 reuses the parent's);
///  - an interface curve per (surface, p < q) of the element sides between parts p and q:
///    parent the surface of the part-p side, partitions {p, q}, its lines oriented as that
///    side's element, no physical group;
///  - a partition point per node where curves of different parts meet (when no piece of a
///    model point is there already): partitions all the parts of those curves;
///  - an entity whose elements are not connected divided into one per connected piece.
/// Surfaces are bounded by the partitioned curves along their elements' sides (+ along the
/// side, - against it), curves by the points at their chain ends.
/// New tags follow the model's largest tag of each dimension. Each node belongs to the
/// first entity, in (dim, tag) order, with an element using it, as Gmsh assigns them.
/// With `topology` false (Mesh.PartitionCreateTopology = 0) no interface curve and no
/// partition point are made: the pieces only, as Gmsh then writes them.
MeshModel partitioned_model(const MeshModel& mesh, const MeshPartition& partition, bool topology = true);

/// One part's file for Mesh.PartitionSplitMeshFiles: the partitioned entities of
/// `partitioned` (from partitioned_model) that are in `part`, boundaries kept to those,
/// the nodes classified again among them, and the model's entities without mesh, as
/// Gmsh 4.8.4 writes it.
MeshModel partition_piece(const MeshModel& partitioned, int part);
/// The same, with the node coordinates given rather than copied from `partitioned`
/// (`xyz` must be those coordinates; `partitioned.xyz` itself is not read and may be
/// empty): a writer of many parts lends one array to each piece in turn, so that a
/// thousand parts of a large mesh never hold a thousand copies of it.
MeshModel partition_piece(const MeshModel& partitioned, int part, std::vector<Vec3> xyz);

}  // namespace sm::io
