// ADCIRC fort.14 and SCHISM hgrid.gr3/.ll from a script's model and 2D mesh: the
// boundary strings come from the faces' curve loops (curves of the physical
// group named "open" are open boundaries), depths from the field named by
// Mesh.DepthField (positive down, e.g. a Bathymetry field).
#pragma once

#include <string>

namespace sm::interp {

class Interpreter;

/// Writes `path` as "fort14" or "gr3" (with hgrid.ll beside it); "" or why not.
std::string save_ocean_grid(Interpreter& in, const std::string& path, const std::string& format);

}  // namespace sm::interp
