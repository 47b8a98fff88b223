// The one lock every call into libnetcdf is made under (field/lonlat_grid.cpp,
// coast/read_gshhg_binned.cpp, io/ugrid_writer.cpp). The library keeps its table of open
// files unguarded, so two threads in it at once (two Python threads running scripts, or a
// grid read while a UGRID file is written) fail ("Not a valid ID") or crash. Each user
// holds it from its open to its close; none calls another while holding it.
#pragma once

#include <mutex>

namespace sm::base {

std::mutex& netcdf_lock();

}  // namespace sm::base
