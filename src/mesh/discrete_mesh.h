// The discrete entities of a merged mesh file (`Merge "file.msh";`, Gmsh 4.8.4's
// discreteVertex/Edge/Face): their points and curves are in the geometry model (a curve
// as the polyline of its nodes, meshed by those nodes), their surfaces only here, as
// elements on the file's node tags; after 1D the surfaces' elements join the mesh on the
// nodes that the points and curves got (meshed as they are, never remeshed).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "base/vec.h"
#include "mesh/mesh_error.h"
#include "mesh/model_mesh.h"

namespace sm {

struct DiscreteSurface {
  std::vector<std::array<std::uint64_t, 3>> triangles;   // the file's node tags
  std::vector<std::array<std::uint64_t, 4>> quads;
};

struct DiscreteEntities {
  std::map<std::uint64_t, Vec3> nodes;                     // the merged files' nodes by tag
  std::map<int, std::uint64_t> vertex_node;                // model point -> its node's tag
  std::map<int, std::vector<std::uint64_t>> curve_nodes;   // discrete curve -> node tags, begin to end
  std::map<int, DiscreteSurface> surfaces;                 // surface tag -> its elements

  bool empty() const { return nodes.empty(); }
};

/// Adds the discrete surfaces to `mesh`, whose points and curves are meshed: an element's
/// node is the node of the point or discrete curve that has its tag, else a node of the
/// surface's own (one per tag, shared between the surfaces). Returns what is wrong
/// (DiscreteCurveChanged: a discrete curve whose mesh no longer has its nodes, split by the
/// 1D repair), or ok().
MeshError add_discrete_surfaces(const DiscreteEntities& d, ModelMesh& mesh);

}  // namespace sm
