#pragma once

namespace radcl {

// Keeps freed memory in the process for reuse. The renderer allocates and frees large per-wave
// vectors; with glibc's defaults each one is a fresh mapping whose pages the kernel faults in and
// clears again, which cost a third of an rpict run's time on a small machine.
void keep_freed_memory();

} // namespace radcl
