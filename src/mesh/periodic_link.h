// A periodic entity's correspondence (Gmsh's $Periodic section), shared by the mesher's
// ModelMesh (mesh/model_mesh.h) and the writers' MeshModel (io/mesh_model.h): each of its
// nodes with the master's node it copies, as indices into the nodes of the mesh that holds
// it, and the map from the master onto it (empty, or 16 numbers row by row).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace sm {

struct PeriodicLink {
  int dim = 0;
  int tag = 0;
  int master = 0;
  std::vector<double> affine;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> nodes;   // (node, master's node)
};

}  // namespace sm
