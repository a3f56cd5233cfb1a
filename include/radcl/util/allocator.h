#pragma once

namespace radcl {

// Keeps freed memory in the process for reuse. The renderer allocates and frees large per-wave
// vectors; with glibc's defaults each one is a fresh mapping whose pages the kernel faults in and
// clears again, which cost a third of an rpict run's time on a small machine.
void keep_freed_memory();

// Has glibc's malloc ask for transparent huge pages (its tunable glibc.malloc.hugetlb=1, read
// only at start-up, so the program runs itself again with it set): a cache build first touches
// a gigabyte or more, and one fault per 2 MB instead of per 4 kB took luminaires' -ab 5 run on
// two cores from 10.1 to 8.4 s. RADCL_HUGE_PAGES=0 turns it off; it does nothing where the
// kernel's huge pages are off, the tunable is set already, or glibc is older than 2.35.
void use_huge_pages(char** argv);

} // namespace radcl
