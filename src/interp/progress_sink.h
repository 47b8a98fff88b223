// Which Progress the kernel calls of a script get: the front end's sink held in
// KernelState::progress, silenced below General.Verbosity 4 (Gmsh's "info" level, where
// the mesh summary is printed too), so `-v 0` to `-v 3` show no progress.
#pragma once

#include "base/progress.h"

namespace sm::interp {

class Interpreter;

/// The sink to hand to coastline import, 1D and 2D meshing now; null when nobody listens.
Progress* progress_sink(Interpreter& in);

}  // namespace sm::interp
