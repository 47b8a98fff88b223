#include "base/release_memory.h"

#include <cstdlib>   // defines __GLIBC__ on glibc (through features.h), tested below

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sm {

void release_free_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace sm
