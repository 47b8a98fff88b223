// The mesh kernel's failures in words: each problem of mesh/mesh_error.h to its diagnostic
// kind of lang/diag_kinds.def, formatted from the error's typed values.
#pragma once

#include <string>
#include <utility>

#include "lang/diag_format.h"
#include "mesh/mesh_error.h"

namespace sm::interp {

/// The kind and message of `e`'s problem (e.problem != None; a crossing, a duplicate
/// point and a limit are worded by their kinds in interp/kernel/mesh_commands.cpp). A 2D
/// problem names its surface by its tag as meshed ("surface N": the caller names a
/// compound's union in the text) and, with a place, ends with it: lon/lat on a geometry,
/// else x, y, z.
std::pair<lang::Diag, std::string> worded_mesh_problem(const MeshError& e);

}  // namespace sm::interp
