#include "radcl/util/allocator.h"

#include <cstdlib> // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace radcl {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // glibc's largest heap (not mmap) allocation, and no trimming of the heap's top.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

} // namespace radcl
