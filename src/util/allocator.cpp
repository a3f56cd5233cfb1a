#include "radcl/util/allocator.h"

#include <cstdlib> // defines __GLIBC__ where it applies
#include <fstream>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <unistd.h>
#endif

namespace radcl {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // Every allocation from the heap, none as its own mapping (glibc maps anything over 32 MB,
  // however the threshold is set, and unmaps it when freed), and no trimming of the heap's top:
  // the cache build's vectors of millions of samples are then reused memory, not fresh pages
  // (page faults and clearing were a quarter of the integrating sphere's -ab 4 run).
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

void use_huge_pages(char** argv) {
#if defined(__GLIBC__) && __GLIBC_PREREQ(2, 35)
  if (const char* e = std::getenv("RADCL_HUGE_PAGES"); e && std::string(e) == "0") return;
  const char* t = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = t ? t : "";
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return; // set: by us or the user
  // Only where the kernel gives huge pages to a mapping that asks (not "[never]").
  std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(thp, mode);
  if (mode.find("[always]") == std::string::npos && mode.find("[madvise]") == std::string::npos)
    return;
  const std::string v =
      tunables.empty() ? "glibc.malloc.hugetlb=1" : tunables + ":glibc.malloc.hugetlb=1";
  if (setenv("GLIBC_TUNABLES", v.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  if (t) // the exec failed: go on as we are
    setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

} // namespace radcl
