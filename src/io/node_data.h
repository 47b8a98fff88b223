// Values per mesh node written beside the mesh (Mesh.NodeData: depth, target size, the
// size criterion that set it): MSH $NodeData, VTK point data, UGRID node variables.
#pragma once

#include <string>
#include <vector>

namespace sm::io {

/// A scalar per node of MeshModel::xyz.
struct NodeData {
  std::string name;          ///< "depth", "size", "criterion"
  std::string units;         ///< "m", "1" (UGRID's units attribute)
  std::string long_name;     ///< what it is, for UGRID's long_name
  std::vector<double> values;
};

}  // namespace sm::io
