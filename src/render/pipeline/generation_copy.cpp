#include "generation_copy.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "radcl/util/error.h"

namespace radcl::render {
GenerationCopy::GenerationCopy(device::Context& ctx, bool wanted) : ctx_(ctx) {
  on_ = wanted && !ctx.zero_copy(); // off: every generation uploaded from the host
  // A generation past this many bytes stays on the host: each of the two copies takes at most
  // the device's largest allocation, a tenth of its memory and 3 GB (a GPU allocates lazily, so
  // an allocation that does not fit would fail at a later command, not here). Waves are split
  // by the batch size long before on a large device.
  std::uint64_t cap = std::uint64_t{3} << 30;
  const device::DeviceInfo& d = ctx.info();
  if (d.max_alloc) cap = std::min(cap, d.max_alloc);
  if (d.global_mem) cap = std::min(cap, d.global_mem / 10);
  max_bytes_ = static_cast<std::size_t>(cap);
}

void GenerationCopy::start_batch() {
  cur_ok_ = false;
  next_ok_ = on_;
}

bool GenerationCopy::copy_current(device::Buffer& dst, std::size_t first, std::size_t n) {
  if (!cur_ok_) return false;
  dst.copy_from(buf_[cur_], n * sizeof(rc_ray), first * sizeof(rc_ray), 0);
  return true;
}

bool GenerationCopy::room(std::size_t rays, std::size_t keep) {
  device::Buffer& b = buf_[1 - cur_];
  const std::size_t bytes = rays * sizeof(rc_ray);
  if (b.size() >= bytes) return true;
  if (bytes > max_bytes_) return false;
  const std::size_t grown =
      std::min(max_bytes_, std::max({bytes, 2 * b.size(), std::size_t{1} << 22}));
  try {
    device::Buffer more(ctx_, grown);
    if (keep) more.copy_from(b, keep * sizeof(rc_ray));
    b = std::move(more);
  } catch (const FatalError&) { // no room on the device: this generation goes by the host
    return false;
  }
  return true;
}

void GenerationCopy::append(const device::Buffer& src, std::size_t at, std::size_t n) {
  if (device::Buffer* b = n ? next_rows(at, n) : nullptr)
    b->copy_from(src, n * sizeof(rc_ray), 0, at * sizeof(rc_ray));
}

void GenerationCopy::upload(const rc_ray* rows, std::size_t at, std::size_t n) {
  if (device::Buffer* b = n ? next_rows(at, n) : nullptr)
    b->write(rows, n * sizeof(rc_ray), at * sizeof(rc_ray));
}

device::Buffer* GenerationCopy::next_rows(std::size_t at, std::size_t n) {
  if (next_ok_ && !room(at + n, at)) next_ok_ = false;
  return next_ok_ ? &buf_[1 - cur_] : nullptr;
}

void GenerationCopy::advance() {
  cur_ = 1 - cur_;
  cur_ok_ = next_ok_;
  next_ok_ = on_;
}

} // namespace radcl::render
