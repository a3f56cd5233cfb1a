// An OpenCL context and in-order queue on one device, with kernel launches.
#pragma once

#include <cstddef>
#include <future>
#include <memory>
#include <vector>

#include "radcl/device/device_info.h"

struct _cl_context;
struct _cl_command_queue;
struct _cl_mem;

namespace radcl::device {

class Kernel;

class Context {
public:
  explicit Context(const DeviceInfo& device);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceInfo& info() const { return info_; }
  // Buffers wrap host memory on devices that share it, unless RADCL_DEVICE_MEMORY=separate
  // asks for device buffers and transfers anyway: the path a discrete GPU takes, run on PoCL
  // so that tests cover it.
  bool zero_copy() const { return info_.host_unified_memory && !separate_; }
  // PoCL's CPU drivers run kernels on a zero-copy buffer's own host allocation, so once the
  // queue is idle the host may copy in and out of it directly. A map/unmap pair instead is two
  // commands through PoCL's worker threads, each waking them: on a small wave those wake-ups
  // cost more than the shading. Other devices (integrated GPUs among them) keep map/unmap.
  bool direct_host() const { return direct_host_; }
  // Waits for the queue when commands are pending (before direct host access).
  void sync();

  // Runs `kernel` over `items` work-items. The global size is rounded up to a multiple of the
  // work-group size (PoCL requires it), so every kernel bounds-checks its index against a count
  // argument. group = 0 picks the kernel's preferred multiple.
  void run(Kernel& kernel, std::size_t items, std::size_t group = 0);
  void finish();
  // A point in the queue: wait_for(mark()) waits for the commands enqueued before it only, and
  // completes their reads (copy_when_drained); those after it go on. Staged copies and pinned
  // room stay until the queue drains.
  struct Mark {
    void* event = nullptr; // cl_event
    std::size_t copies = 0;
  };
  Mark mark();
  void wait_for(Mark& m);
  // A copy of `bytes` at `src` that stays valid until the queue drains (finish, or a blocking
  // read): the source of a transfer enqueued without waiting.
  const void* stage(const void* src, std::size_t bytes);
  // On a device with its own memory, room for a small transfer in pinned host memory, valid
  // until the queue drains; nullptr where there is none (large transfers, zero-copy devices).
  // NVIDIA's driver makes a transfer from or to pageable memory wait; from pinned memory it
  // does not, so a wave's reads and writes share one wait (docs/internals.md).
  void* pinned(std::size_t bytes);
  bool pins() const { return use_pinned_; }
  // Pinned host memory of the caller's own, held until free_pinned (or the context ends): a
  // queue the host fills (Embree's hits) goes to the device from there without a copy. Where
  // the device shares the host's memory it is a zero-copy buffer's own allocation, which the
  // kernels read in place (Buffer::view). nullptr where there is none (RADCL_PINNED=0, the
  // driver refused).
  void* alloc_pinned(std::size_t bytes);
  // Gives back memory alloc_pinned gave; false (nothing done) for any other pointer.
  bool free_pinned(void* p);
  // Whether [p, p + bytes) lies in memory alloc_pinned gave.
  bool is_pinned(const void* p, std::size_t bytes) const;
  // The zero-copy buffer alloc_pinned gave that holds [p, p + bytes), with p's offset in it;
  // nullptr where none does or the offset is not one a sub-buffer may start at.
  _cl_mem* shared_region(const void* p, std::size_t bytes, std::size_t* offset) const;
  // Copies `bytes` from `from` (pinned room a read is filling) to `to` once the queue drains.
  void copy_when_drained(const void* from, void* to, std::size_t bytes);
  // Every command enqueued so far has completed: reads into pinned room reach their
  // destinations, and the staged copies and pinned room may go.
  void drained();

  _cl_context* handle() const { return context_; }
  _cl_command_queue* queue() const { return queue_; }

private:
  DeviceInfo info_;
  _cl_context* context_ = nullptr;
  _cl_command_queue* queue_ = nullptr;
  bool direct_host_ = false;
  bool separate_ = false; // RADCL_DEVICE_MEMORY=separate
  bool pending_ = false;  // a kernel was enqueued since the last finish
  // Copies behind transfers still in flight; blocks are kept for reuse once drained.
  std::vector<std::vector<char>> staged_, spare_;
  // Pinned host memory: mapped CL_MEM_ALLOC_HOST_PTR buffers, used from the front between
  // drains. RADCL_PINNED=0 turns it off (to measure it).
  struct PinnedBlock {
    void* mem; // cl_mem
    char* host;
    std::size_t size, used;
    bool shared = false; // a zero-copy buffer over an aligned host allocation
  };
  bool use_pinned_ = false;
  bool share_ = false;           // alloc_pinned gives zero-copy buffers' memory
  std::size_t sub_align_ = 4096; // where a sub-buffer may start (CL_DEVICE_MEM_BASE_ADDR_ALIGN)
  std::vector<PinnedBlock> pinned_, owned_;
  std::size_t pin_block_ = 0;
  struct CopyBack {
    const void* from;
    void* to;
    std::size_t bytes;
  };
  std::vector<CopyBack> copy_back_;
  void release_pinned();
};

// The device chosen by RADCL_DEVICE (see select_device), shared by the whole process.
Context& default_context();

// Starts default_context()'s set-up on another thread, so that the driver's start-up (a few
// tenths of a second for NVIDIA's) overlaps the scene's loading; a later default_context() waits
// for it. A failure there is not reported: default_context() tries again and reports it. Not
// for a process that forks before it uses the device.
std::future<void> start_default_context();

} // namespace radcl::device
