#include "common/allocator.hpp"

#include <cstdlib>  // defines __GLIBC__ with glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pagor::app {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // glibc's own ceiling for the mapping threshold is 32 MiB on 64-bit systems (a larger value is
  // refused and the default kept).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace pagor::app
