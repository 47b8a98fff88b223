// Meshing and saving from the interpreter: `Mesh 1;` / `Save "f.msh";` in scripts and
// `stereomesh x.geo -1 -o x.msh -format msh22` on the command line (docs/interpreter.md).
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh_stats.h"

namespace sm::interp {

class Interpreter;

/// `-1` / `-2` after the scripts ran: meshes the model up to `dim` (1 or 2) and
/// writes it atomically to `output` (default: the first script's name with `.msh`) in
/// `format` (a name of io/output_format.h; empty: by Mesh.Format or the extension).
/// Failures become diagnostics (kernel errors with notes at the statements that created
/// the entities involved); returns false then.
bool mesh_from_command_line(Interpreter& in, int dim, const std::string& output, const std::string& format,
                            const std::string& first_script);

/// The file -1/-2 write without -o: the first script's name with the format's extension
/// (or the format's fixed name, fort.14), beside it. (For a script named x.msh that is
/// the script itself: the command line refuses that before the run.)
std::string default_mesh_output(const std::string& first_script, const std::string& format);

/// The meshing half of mesh_from_command_line, writing nothing (the Python module keeps
/// the mesh in memory): false, with the failure reported, when the mesh cannot be made.
bool mesh_after_scripts(Interpreter& in, int dim);

/// A field kind whose set-up took less than this (seconds) is counted in the account's
/// "fields" stage instead of having its own.
inline constexpr double kMinFieldSeconds = 0.1;

/// Where the run's time went so far (interp/stage_clock.h): the script's evaluation, the
/// import, "fields" (looking fields up and the kinds under kMinFieldSeconds), each other
/// kind as "field <Kind>", 1D, the 2D mesher's stages, the statistics and the writing,
/// each once in the order it first ran; they add up to the time since the interpreter
/// started.
std::vector<StageTime> run_stages(Interpreter& in);

/// The end of a run (after the scripts and -1/-2's meshing and writing): with
/// `print_time`, prints the account as the `Time:` line on stderr at General.Verbosity 4;
/// returns the last mesh's statistics as JSON with the same stages: the 2D figures, or
/// the 1D ones (mesh/mesh_stats.h curve_stats_json) when the last mesh was `Mesh 1;`/-1
/// ("" when no mesh was made).
std::string finish_run(Interpreter& in, bool print_time = true);

}  // namespace sm::interp
