#include "radcl/device/buffer.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "radcl/device/cl.h"
#include "radcl/device/context.h"
#include "radcl/util/error.h"

namespace radcl::device {
namespace {
constexpr std::size_t kAlign = 4096; // page alignment lets the runtime use the memory directly
std::atomic<std::size_t> bytes_up{0}, bytes_down{0}, waits{0};
} // namespace

Transfers transfers() {
  return {bytes_up.load(), bytes_down.load(), waits.load()};
}

void note_wait() {
  ++waits;
}

Buffer::Buffer(Context& ctx, std::size_t bytes) : ctx_(&ctx), bytes_(bytes) {
  if (bytes == 0) throw FatalError("zero-sized device buffer");
  if (ctx.zero_copy()) {
    host_ = std::aligned_alloc(kAlign, (bytes + kAlign - 1) / kAlign * kAlign);
    if (!host_) throw FatalError("out of memory allocating " + std::to_string(bytes) + " bytes");
    try {
      RADCL_CL_CREATE(mem_, clCreateBuffer(ctx.handle(), CL_MEM_READ_WRITE | CL_MEM_USE_HOST_PTR,
                                           bytes, host_, &radcl_status_));
    } catch (...) {
      std::free(host_);
      throw;
    }
  } else {
    RADCL_CL_CREATE(
        mem_, clCreateBuffer(ctx.handle(), CL_MEM_READ_WRITE, bytes, nullptr, &radcl_status_));
  }
}

Buffer Buffer::view(Context& ctx, const void* p, std::size_t bytes) {
  Buffer b;
  std::size_t at = 0;
  cl_mem parent = bytes ? ctx.shared_region(p, bytes, &at) : nullptr;
  if (!parent) return b;
  const cl_buffer_region region{at, bytes};
  cl_int st = CL_SUCCESS;
  cl_mem m =
      clCreateSubBuffer(parent, CL_MEM_READ_WRITE, CL_BUFFER_CREATE_TYPE_REGION, &region, &st);
  if (st != CL_SUCCESS || !m) return b;
  b.ctx_ = &ctx;
  b.mem_ = m;
  b.host_ = const_cast<void*>(p);
  b.bytes_ = bytes;
  b.owns_host_ = false;
  return b;
}

void Buffer::release() {
  if (mem_) clReleaseMemObject(mem_);
  if (owns_host_) std::free(host_);
  owns_host_ = true;
  mem_ = nullptr;
  host_ = nullptr;
}

Buffer::~Buffer() {
  release();
}

Buffer::Buffer(Buffer&& o) noexcept
    : ctx_(o.ctx_), mem_(std::exchange(o.mem_, nullptr)), host_(std::exchange(o.host_, nullptr)),
      bytes_(std::exchange(o.bytes_, 0)), owns_host_(std::exchange(o.owns_host_, true)) {}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    release();
    ctx_ = o.ctx_;
    mem_ = std::exchange(o.mem_, nullptr);
    host_ = std::exchange(o.host_, nullptr);
    bytes_ = std::exchange(o.bytes_, 0);
    owns_host_ = std::exchange(o.owns_host_, true);
  }
  return *this;
}

void* Buffer::map() {
  if (host_ && ctx_->direct_host()) {
    ctx_->sync();
    return host_;
  }
  void* p = nullptr;
  RADCL_CL_CREATE(p, clEnqueueMapBuffer(ctx_->queue(), mem_, CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0,
                                        bytes_, 0, nullptr, nullptr, &radcl_status_));
  note_wait();
  return p;
}

void Buffer::unmap(void* ptr) {
  if (host_ && ctx_->direct_host()) return;
  RADCL_CL(clEnqueueUnmapMemObject(ctx_->queue(), mem_, ptr, 0, nullptr, nullptr));
}

void Buffer::write(const void* src, std::size_t bytes, std::size_t offset) {
  if (offset + bytes > bytes_) throw FatalError("device buffer write out of range");
  if (host_) {
    void* p = map();
    std::memcpy(static_cast<char*>(p) + offset, src, bytes);
    unmap(p);
  } else {
    // Without waiting: the queue is in order, so later commands see the data, and the copy
    // the transfer reads from lives until the queue next drains.
    bytes_up += bytes;
    const void* staged = ctx_->stage(src, bytes);
    RADCL_CL(clEnqueueWriteBuffer(ctx_->queue(), mem_, CL_FALSE, offset, bytes, staged, 0, nullptr,
                                  nullptr));
  }
}

void Buffer::copy_from(const Buffer& src, std::size_t bytes, std::size_t src_offset,
                       std::size_t offset) {
  if (offset + bytes > bytes_ || src_offset + bytes > src.bytes_)
    throw FatalError("device buffer copy out of range");
  if (bytes == 0) return;
  if (host_ && src.host_ && ctx_->direct_host()) {
    ctx_->sync();
    std::memcpy(static_cast<char*>(host_) + offset,
                static_cast<const char*>(src.host_) + src_offset, bytes);
    return;
  }
  RADCL_CL(clEnqueueCopyBuffer(ctx_->queue(), src.mem_, mem_, src_offset, offset, bytes, 0, nullptr,
                               nullptr));
}

void Buffer::write_pinned(const void* src, std::size_t bytes, std::size_t offset) {
  if (host_ || !ctx_->is_pinned(src, bytes)) {
    write(src, bytes, offset);
    return;
  }
  if (offset + bytes > bytes_) throw FatalError("device buffer write out of range");
  if (bytes == 0) return;
  bytes_up += bytes;
  RADCL_CL(
      clEnqueueWriteBuffer(ctx_->queue(), mem_, CL_FALSE, offset, bytes, src, 0, nullptr, nullptr));
}

const void* Buffer::peek(std::size_t bytes, std::vector<char>& staging) const {
  return peek_into(bytes, staging, false);
}

const void* Buffer::peek_later(std::size_t bytes, std::vector<char>& staging) const {
  return peek_into(bytes, staging, true);
}

const void* Buffer::peek_into(std::size_t bytes, std::vector<char>& staging, bool later) const {
  if (bytes > bytes_) throw FatalError("device buffer read out of range");
  if (host_ && ctx_->direct_host()) {
    ctx_->sync();
    return host_;
  }
  if (staging.size() < bytes) staging.resize(bytes);
  if (bytes == 0) return staging.data();
  if (later)
    read_later(staging.data(), bytes);
  else
    read(staging.data(), bytes);
  return staging.data();
}

void Buffer::read_later(void* dst, std::size_t bytes, std::size_t offset) const {
  if (offset + bytes > bytes_) throw FatalError("device buffer read out of range");
  if (bytes == 0) return;
  if (host_) {
    read(dst, bytes, offset);
    return;
  }
  bytes_down += bytes;
  if (void* p = ctx_->pinned(bytes)) { // into pinned room, copied to dst when the queue drains
    RADCL_CL(
        clEnqueueReadBuffer(ctx_->queue(), mem_, CL_FALSE, offset, bytes, p, 0, nullptr, nullptr));
    ctx_->copy_when_drained(p, dst, bytes);
    return;
  }
  RADCL_CL(
      clEnqueueReadBuffer(ctx_->queue(), mem_, CL_FALSE, offset, bytes, dst, 0, nullptr, nullptr));
}

void Buffer::read(void* dst, std::size_t bytes, std::size_t offset) const {
  if (offset + bytes > bytes_) throw FatalError("device buffer read out of range");
  if (host_) {
    auto* self = const_cast<Buffer*>(this);
    void* p = self->map();
    std::memcpy(dst, static_cast<const char*>(p) + offset, bytes);
    self->unmap(p);
  } else if (ctx_->pins()) {
    read_later(dst, bytes, offset); // a small one through pinned room: shorter than a pageable read
    ctx_->finish();
  } else {
    bytes_down += bytes;
    RADCL_CL(
        clEnqueueReadBuffer(ctx_->queue(), mem_, CL_TRUE, offset, bytes, dst, 0, nullptr, nullptr));
    note_wait();
    ctx_->drained(); // a blocking read in an in-order queue waited for everything before it
  }
}

} // namespace radcl::device
