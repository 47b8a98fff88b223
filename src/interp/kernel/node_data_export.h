// Mesh.NodeData: the values at the mesh nodes that MSH, VTK and UGRID files carry beside
// the mesh (the depth of Mesh.DepthField, the target size the mesher aimed at, and the
// criterion of the background Min that set it), so that a viewer colours by them.
#pragma once

#include <string>
#include <vector>

#include "io/mesh_model.h"
#include "io/node_data.h"

namespace sm::interp {

class Interpreter;

/// The values Mesh.NodeData names, at the nodes of `mm` (in space: before any change of
/// node coordinates), into `out`; "" or why not (no depth field, no size field).
std::string node_data_for_output(Interpreter& in, const io::MeshModel& mm, std::vector<io::NodeData>& out);

/// The same for the names given (depth, size, criterion) instead of Mesh.NodeData's.
std::string node_data_named(Interpreter& in, const io::MeshModel& mm, const std::vector<std::string>& names,
                            std::vector<io::NodeData>& out);

}  // namespace sm::interp
