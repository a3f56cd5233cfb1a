#include "radcl/util/allocator.h"

#include <cstdlib> // defines __GLIBC__ where it applies

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace radcl {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // Every allocation from the heap, none as its own mapping (glibc maps anything over 32 MB,
  // however the threshold is set, and unmaps it when freed), and no trimming of the heap's top:
  // the cache build's vectors of millions of samples are then reused memory, not fresh pages
  // (page faults and clearing were a quarter of the integrating sphere's -ab 4 run).
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

} // namespace radcl
