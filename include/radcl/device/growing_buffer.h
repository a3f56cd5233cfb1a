// A device copy of a host array that changes only at its end (the irradiance cache's records
// and lookup nodes, the leak lists): each update writes the elements past those the caller
// knows unchanged, into room kept with half again to spare, so a growing array costs its new
// elements rather than a fresh buffer and a transfer of the whole.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "radcl/device/buffer.h"

namespace radcl::device {

class GrowingBuffer {
public:
  // `v`'s first `unchanged` elements are those of the last update (0: none may be trusted).
  template <class T> void update(Context& ctx, const std::vector<T>& v, std::size_t unchanged) {
    const std::size_t bytes = std::max<std::size_t>(v.size(), 1) * sizeof(T);
    std::size_t keep = std::min(unchanged * sizeof(T), valid_);
    if (buf_.size() < bytes) {
      buf_ = Buffer(ctx, bytes + bytes / 2);
      keep = 0;
    }
    const std::size_t total = v.size() * sizeof(T);
    keep = std::min(keep, total);
    if (total > keep)
      buf_.write(reinterpret_cast<const char*>(v.data()) + keep, total - keep, keep);
    valid_ = total;
  }
  const Buffer& buffer() const { return buf_; }

private:
  Buffer buf_;
  std::size_t valid_ = 0; // bytes that hold the last update
};

} // namespace radcl::device
