// Where the program's own files are: the stdlib templates and the shipped data (data/)
// live together in one "share" folder, found from the place of the running binary or
// library, never from a path compiled in, so a build tree, an installed prefix and a
// copied prefix all work with the source tree gone.
//
//   <prefix>/bin/stereomesh                -> <prefix>/share/stereomesh/{stdlib,data}
//   <build>/stereomesh                     -> <build>/share/stereomesh   (links made by CMake)
//   <build>/python/stereomesh.*.so         -> <build>/share/stereomesh
//   <prefix>/lib/python3/dist-packages/... -> <prefix>/share/stereomesh
#pragma once

#include <filesystem>
#include <string>

namespace sm::base {

/// The share folder for a binary or shared library at `anchor` (a file path):
/// the first of `<dir>/../share/stereomesh`, `<dir>/share/stereomesh` and
/// `<dir>/../../../share/stereomesh` that holds a stdlib/ folder; empty when none does.
std::filesystem::path find_share_dir(const std::filesystem::path& anchor);

/// The running program's own file (/proc/self/exe); empty when it cannot be read.
std::filesystem::path executable_path();

/// The file of the shared object (or program) that holds `address` (dladdr); empty when
/// unknown. The Python module passes one of its own functions.
std::filesystem::path object_path_of(const void* address);

}  // namespace sm::base
