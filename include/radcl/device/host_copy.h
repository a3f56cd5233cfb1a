// Copies in host memory with every core: a wave's rays, hits and transfers are hundreds of
// megabytes, and a copy on one thread holds the other cores idle.
#pragma once

#include <cstddef>

namespace radcl::device {

void parallel_copy(void* dst, const void* src, std::size_t bytes);

} // namespace radcl::device
