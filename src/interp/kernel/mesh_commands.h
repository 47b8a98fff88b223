// Meshing and saving from the interpreter: `Mesh 1;` / `Save "f.msh";` in scripts and
// `stereomesh x.geo -1 -o x.msh -format msh22` on the command line (gmsh-reference 5).
#pragma once

#include <string>

namespace sm::interp {

class Interpreter;

/// `-1` / `-2` after the scripts ran: meshes the model up to `dim` (1 or 2) and
/// writes it atomically to `output` (default: the first script's name with `.msh`) in
/// `format` (a name of io/output_format.h; empty: by Mesh.Format or the extension).
/// Failures become diagnostics (kernel errors with notes at the statements that created
/// the entities involved); returns false then.
bool mesh_from_command_line(Interpreter& in, int dim, const std::string& output, const std::string& format,
                            const std::string& first_script);

}  // namespace sm::interp
