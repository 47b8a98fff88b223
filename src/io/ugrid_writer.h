// UGRID 1.0 netCDF (the unstructured-grid convention on top of CF that QGIS through
// MDAL, xugrid, Delft3D FM and seamsh's users read): one 2D mesh topology variable,
// node longitude / latitude (and the Cartesian x y z of the mesh), the faces'
// node lists (anticlockwise seen from outside the sphere, 0-based, -1 filling
// triangles where quadrangles make the row 4 long), the boundary edges with their
// kind (mainland, island, open) and physical curve group, and the depth when a
// depth field is set. Written as netCDF's 64-bit-offset classic format, which
// every netCDF reader opens.
#pragma once

#include <string>

#include "io/mesh_model.h"
#include "io/node_data.h"
#include "io/ocean_grid.h"

namespace sm::io {

/// The file's bytes (the netCDF file built in memory): tests, and the writer below.
/// Empty with *error on failure.
/// `node_data`: more node variables, mesh2d_node_<name> (Mesh.NodeData).
/// `element_part`: per entity, per element, its partition (io/mesh_partition.h), written
/// as the face variable mesh2d_face_partition; nullptr: none.
std::string ugrid_to_bytes(const MeshModel& mesh, const OceanGridOptions& opt, std::string* error,
                           const std::vector<NodeData>& node_data = {},
                           const std::vector<std::vector<int>>* element_part = nullptr);

/// Writes `path` atomically (base/output_file.h); *error is the reason, without the path.
bool save_ugrid(const MeshModel& mesh, const OceanGridOptions& opt, const std::vector<NodeData>& node_data,
                const std::vector<std::vector<int>>* element_part, const std::string& path, std::string* error);

}  // namespace sm::io
