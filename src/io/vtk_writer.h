// VTK writers for people's viewers (ParaView, VisIt): legacy .vtk (ASCII or
// big-endian binary) and XML .vtu (ASCII or base64 binary), with cell data
// (entity, physical group, quality rho) and optional node data (size field...).
#pragma once

#include <string>
#include <vector>

#include "io/mesh_model.h"
#include "io/node_data.h"

namespace sm::io {

struct VtkOptions {
  bool xml = false;      // .vtu instead of legacy .vtk
  bool binary = false;   // legacy: big-endian binary; xml: base64 "binary"
  bool save_all = false; // as Mesh.SaveAll: also entities outside physical groups
  std::vector<NodeData> node_data;
  /// Per entity, per element: its partition (io/mesh_partition.h), written as the cell
  /// data "partition"; nullptr: none.
  const std::vector<std::vector<int>>* element_part = nullptr;
};

/// Writes the elements of the highest dimension present (triangles of a 2D
/// mesh, lines of a 1D mesh) and the nodes they use.
std::string vtk_to_string(const MeshModel& mesh, const VtkOptions& opt);
/// Writes atomically; *error is the reason on failure, without the path (see msh_writer.h).
bool save_vtk(const MeshModel& mesh, const VtkOptions& opt, const std::string& path, std::string* error);

}  // namespace sm::io
