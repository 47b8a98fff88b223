// The process's one libnetcdf lock (netcdf_lock.h).
#include "base/netcdf_lock.h"

namespace sm::base {

std::mutex& netcdf_lock() {
  static std::mutex lock;   // constant-initialised: no guard that could wait on anything
  return lock;
}

}  // namespace sm::base
