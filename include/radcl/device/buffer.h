// Device buffers. On a device that shares the host's memory (PoCL on the CPU) a buffer wraps a
// page-aligned host allocation (CL_MEM_USE_HOST_PTR): reads and writes are plain copies in host
// memory around a map/unmap that only synchronises, and no transfer ever happens. On a GPU the
// buffer lives in device memory and reads/writes are transfers.
#pragma once

#include <cstddef>
#include <vector>

struct _cl_mem;

namespace radcl::device {

class Context;

// Bytes moved between host and device memory since the process began (transfers only: a
// buffer the host reads in place moves nothing), and the times the host waited for the device
// (finishes, blocking reads and maps: on a GPU each costs the latency of a round trip), for
// RADCL_PROFILE.
struct Transfers {
  std::size_t up = 0, down = 0, waits = 0;
};
Transfers transfers();
// Counts one wait of the host for the device (the device module's own bookkeeping).
void note_wait();

class Buffer {
public:
  Buffer() = default;
  Buffer(Context& ctx, std::size_t bytes);
  ~Buffer();
  Buffer(Buffer&& o) noexcept;
  Buffer& operator=(Buffer&& o) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  std::size_t size() const { return bytes_; }
  bool zero_copy() const { return host_ != nullptr; }
  _cl_mem* handle() const { return mem_; }

  void write(const void* src, std::size_t bytes, std::size_t offset = 0);
  // A write straight from memory Context::alloc_pinned gave, without a copy: `src` must stay
  // as it is until the queue drains (elsewhere it is an ordinary write).
  void write_pinned(const void* src, std::size_t bytes, std::size_t offset = 0);
  void read(void* dst, std::size_t bytes, std::size_t offset = 0) const;
  // `bytes` of `src` from src_offset to this buffer at `offset`, on the device, without waiting
  // (in queue order with the commands around it).
  void copy_from(const Buffer& src, std::size_t bytes, std::size_t src_offset = 0,
                 std::size_t offset = 0);
  // A read queued without waiting: `dst` is filled once the context finishes
  // (Context::finish), so several reads cost one wait. Where the host reads the buffer
  // directly it is an ordinary read.
  void read_later(void* dst, std::size_t bytes, std::size_t offset = 0) const;

  // The kernels' view of [p, p + bytes) in place, where that lies in a zero-copy buffer of
  // Context::alloc_pinned (a sub-buffer: nothing is copied); an empty buffer (no handle)
  // elsewhere. The memory stays its allocator's.
  static Buffer view(Context& ctx, const void* p, std::size_t bytes);

  template <class T> static Buffer from(Context& ctx, const std::vector<T>& v) {
    Buffer b(ctx, v.empty() ? sizeof(T) : v.size() * sizeof(T));
    if (!v.empty()) b.write(v.data(), v.size() * sizeof(T));
    return b;
  }
  template <class T> std::vector<T> to_vector(std::size_t n) const {
    std::vector<T> v(n);
    if (n) read(v.data(), n * sizeof(T));
    return v;
  }

  // The first `bytes` of the buffer for reading on the host, after every command before: the
  // buffer's own allocation where the host may read it directly (PoCL), else a copy read into
  // `staging` (one transfer of just those bytes, where mapping would move the whole buffer
  // both ways on a discrete GPU).
  const void* peek(std::size_t bytes, std::vector<char>& staging) const;
  // The same as a read_later: the bytes are there once the context finishes.
  const void* peek_later(std::size_t bytes, std::vector<char>& staging) const;
  // Maps the whole buffer for host access (blocking); returns the host pointer. For a
  // zero-copy buffer this is the buffer's own host allocation.
  void* map();
  void unmap(void* ptr);
  const void* host_allocation() const { return host_; }

private:
  Context* ctx_ = nullptr;
  _cl_mem* mem_ = nullptr;
  void* host_ = nullptr;
  std::size_t bytes_ = 0;
  bool owns_host_ = true; // false for a view
  void release();
  const void* peek_into(std::size_t bytes, std::vector<char>& staging, bool later) const;
};

} // namespace radcl::device
