// The mesh as every writer sees it: nodes classified on model entities
// (Gmsh's view of a mesh: each node belongs to exactly one point, curve or
// surface), independent of how the mesher stores its triangulation.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "mesh/periodic_link.h"

namespace sm::io {

/// Gmsh element type numbers (MSH formats).
enum class ElementType : int { Line2 = 1, Triangle3 = 2, Quad4 = 3, Point1 = 15 };

int nodes_per_element(ElementType type);

/// The mesh of one model entity, or one more block of elements of another type of an
/// entity listed before (a surface with triangles and quadrangles: its second record has
/// the same dim and tag, type Quad4, no nodes; see is_extra_block). Node indices refer
/// to MeshModel::xyz.
struct EntityMesh {
  int dim = 0;                           // 0 point, 1 curve, 2 surface
  int tag = 0;                           // model tag (> 0)
  std::vector<int> physical_tags;        // groups this entity belongs to
  std::vector<int> boundary;             // signed tags of bounding entities of dim-1
                                         // (curve: +begin, -end point; surface: signed curves)
  std::vector<std::uint32_t> nodes;      // nodes classified on this entity (for a curve: interior only)
  std::vector<double> params;            // empty, or dim values per node (curve t; surface u v)
  ElementType type = ElementType::Point1;
  std::vector<std::uint32_t> connectivity;  // nodes_per_element(type) node indices per element
  // A partitioned entity (io/partitioned_model.h; MSH 4.1's $PartitionedEntities): the
  // parts it is in (1..MeshModel::num_partitions) and its model entity; empty for the
  // model's own entities.
  std::vector<int> partitions{};
  int parent_dim = 0;
  int parent_tag = 0;
};

struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;  // may be empty
};

struct MeshModel {
  std::vector<Vec3> xyz;                 // every node, in any order
  std::vector<EntityMesh> entities;      // any order: writers sort by (dim, tag)
  std::vector<PhysicalGroup> physicals;
  int num_partitions = 0;                // > 0: the mesh is in the partitioned entities
  std::vector<PeriodicLink> periodic;  // by increasing (dim, tag)

  std::size_t element_count() const;
};

/// Checks the model (every used node owned by exactly one entity, element
/// node indices in range, tags positive and unique per element type, an entity's
/// extra blocks without nodes). Returns an empty string
/// when valid, else what is wrong; writers refuse invalid models.
std::string validate_mesh_model(const MeshModel& mesh);

/// The indices of mesh.entities by increasing (dim, tag, element type): the order every
/// writer and the partitioning go through them in ((dim, tag, type) is unique in a valid
/// model).
std::vector<std::size_t> entity_order(const MeshModel& mesh);

/// In entity_order, whether order[k] continues the entity of order[k - 1] (another block
/// of its elements): writers list the entity and its nodes once.
bool is_extra_block(const MeshModel& mesh, const std::vector<std::size_t>& order, std::size_t k);

}  // namespace sm::io
