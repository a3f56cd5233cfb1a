#include "radcl/device/host_copy.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

namespace radcl::device {

void parallel_copy(void* dst, const void* src, std::size_t bytes) {
  constexpr std::size_t kBlock = std::size_t{1} << 18;
  if (bytes < 4 * kBlock) {
    std::memcpy(dst, src, bytes);
    return;
  }
  tbb::parallel_for(std::size_t{0}, (bytes + kBlock - 1) / kBlock, [&](std::size_t k) {
    const std::size_t at = k * kBlock;
    std::memcpy(static_cast<char*>(dst) + at, static_cast<const char*>(src) + at,
                std::min(kBlock, bytes - at));
  });
}

} // namespace radcl::device
