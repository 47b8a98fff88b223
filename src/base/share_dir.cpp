#include "base/share_dir.h"

#include <dlfcn.h>

#include <system_error>

namespace sm::base {

namespace fs = std::filesystem;

fs::path find_share_dir(const fs::path& anchor) {
  if (anchor.empty()) return {};
  std::error_code ec;
  const fs::path dir = anchor.parent_path();
  // bin/ of a prefix or build/python/; the build tree's own binary; lib/python3/dist-packages/.
  const fs::path up3 = dir.parent_path().parent_path().parent_path();
  for (const fs::path& candidate :
       {dir.parent_path() / "share" / "stereomesh", dir / "share" / "stereomesh", up3 / "share" / "stereomesh"}) {
    if (fs::is_directory(candidate / "stdlib", ec)) return candidate.lexically_normal();
  }
  return {};
}

fs::path executable_path() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

fs::path object_path_of(const void* address) {
  Dl_info info{};
  if (dladdr(address, &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  fs::path p = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path(info.dli_fname) : p;
}

}  // namespace sm::base
