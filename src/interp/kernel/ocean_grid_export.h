// ADCIRC fort.14 and SCHISM hgrid.gr3/.ll from a script's model and 2D mesh: the
// boundary strings come from the faces' curve loops (curves of the physical
// group named "open" are open boundaries), depths from the field named by
// Mesh.DepthField (positive down, e.g. a Bathymetry field).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/mesh_model.h"
#include "io/ocean_grid.h"

namespace sm::interp {

class Interpreter;

/// What the fort.14 / hgrid.gr3 writers read besides `mm` (the model's 2D mesh), for the
/// file `path` (its name is the grid's title): the sphere, depths, boundary strings.
/// "" or why not (no 2D mesh, a depth field that cannot be built). `node_index` is the
/// ModelMesh -> `mm` node map from io::from_model_mesh, in which the strings are given.
std::string ocean_grid_options(Interpreter& in, const std::string& path, const io::MeshModel& mm,
                               const std::vector<std::uint32_t>& node_index, io::OceanGridOptions& opt);

}  // namespace sm::interp
