#include "radcl/device/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

#include "radcl/device/buffer.h"
#include "radcl/device/cl.h"
#include "radcl/device/host_copy.h"
#include "radcl/device/program.h"

namespace radcl::device {

Context::Context(const DeviceInfo& device) : info_(device) {
  const char* mem = std::getenv("RADCL_DEVICE_MEMORY");
  separate_ = mem && std::string(mem) == "separate";
  direct_host_ = zero_copy() && device.kind == DeviceKind::CPU &&
                 device.platform_name.find("Portable Computing Language") != std::string::npos &&
                 !std::getenv("RADCL_MAP_BUFFERS"); // "1": map/unmap as on other devices
  cl_device_id id = static_cast<cl_device_id>(device.id);
  cl_context_properties props[] = {CL_CONTEXT_PLATFORM,
                                   reinterpret_cast<cl_context_properties>(device.platform), 0};
  RADCL_CL_CREATE(context_, clCreateContext(props, 1, &id, nullptr, nullptr, &radcl_status_));
  try {
    RADCL_CL_CREATE(queue_,
                    clCreateCommandQueueWithProperties(context_, id, nullptr, &radcl_status_));
  } catch (...) {
    clReleaseContext(context_);
    throw;
  }
  const char* pin = std::getenv("RADCL_PINNED");
  use_pinned_ = !zero_copy() && !(pin && std::string(pin) == "0");
  share_ = zero_copy() && !(pin && std::string(pin) == "0");
  cl_uint bits = 0;
  if (clGetDeviceInfo(id, CL_DEVICE_MEM_BASE_ADDR_ALIGN, sizeof bits, &bits, nullptr) ==
          CL_SUCCESS &&
      bits >= 8)
    sub_align_ = bits / 8;
}

Context::~Context() {
  if (queue_) {
    clFinish(queue_);
    release_pinned();
    clReleaseCommandQueue(queue_);
  }
  if (context_) clReleaseContext(context_);
}

namespace {
// Transfers go through pinned memory, which the device reads and writes at the bus's speed
// (pageable memory goes through the driver's own staging, a copy on one core): up to this much
// of it in all, in blocks of at least this size.
constexpr std::size_t kPinnedTotal = std::size_t{2} << 30;
constexpr std::size_t kPinnedBlock = std::size_t{8} << 20;

} // namespace

void* Context::pinned(std::size_t bytes) {
  if (!use_pinned_) return nullptr;
  bytes = (bytes + 63) / 64 * 64;
  for (;; ++pin_block_) {
    if (pin_block_ == pinned_.size()) {
      const std::size_t size = std::max(kPinnedBlock, bytes);
      std::size_t held = 0;
      for (const PinnedBlock& b : pinned_)
        held += b.size;
      if (held + size > kPinnedTotal) return nullptr; // from where the data lies
      cl_int st = CL_SUCCESS;
      cl_mem m =
          clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, size, nullptr, &st);
      void* h = nullptr;
      if (st == CL_SUCCESS) // blocking, but once per block for the whole run
        h = clEnqueueMapBuffer(queue_, m, CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0, size, 0, nullptr,
                               nullptr, &st);
      if (st != CL_SUCCESS || !h) { // no pinned memory here: transfer from where data lies
        if (m) clReleaseMemObject(m);
        use_pinned_ = false;
        return nullptr;
      }
      pinned_.push_back({m, static_cast<char*>(h), size, 0});
    }
    PinnedBlock& b = pinned_[pin_block_];
    if (b.used + bytes <= b.size) {
      void* p = b.host + b.used;
      b.used += bytes;
      return p;
    }
  }
}

void* Context::alloc_pinned(std::size_t bytes) {
  if (share_ && bytes > 0) {
    constexpr std::size_t kPage = 4096; // page alignment lets PoCL use the memory directly
    void* h = std::aligned_alloc(kPage, (bytes + kPage - 1) / kPage * kPage);
    if (!h) return nullptr;
    cl_int st = CL_SUCCESS;
    cl_mem m = clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_USE_HOST_PTR, bytes, h, &st);
    if (st != CL_SUCCESS) {
      std::free(h);
      return nullptr;
    }
    owned_.push_back({m, static_cast<char*>(h), bytes, bytes, true});
    return h;
  }
  if (!use_pinned_ || bytes == 0) return nullptr;
  cl_int st = CL_SUCCESS;
  cl_mem m =
      clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, bytes, nullptr, &st);
  void* h = nullptr;
  if (st == CL_SUCCESS)
    h = clEnqueueMapBuffer(queue_, m, CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0, bytes, 0, nullptr,
                           nullptr, &st);
  if (st != CL_SUCCESS || !h) {
    if (m) clReleaseMemObject(m);
    return nullptr;
  }
  owned_.push_back({m, static_cast<char*>(h), bytes, bytes});
  return h;
}

bool Context::free_pinned(void* p) {
  for (std::size_t k = 0; k < owned_.size(); ++k)
    if (owned_[k].host == p) {
      cl_mem m = static_cast<cl_mem>(owned_[k].mem);
      clFinish(queue_); // no transfer or kernel may still read it
      if (owned_[k].shared) {
        clReleaseMemObject(m);
        std::free(p);
      } else {
        clEnqueueUnmapMemObject(queue_, m, p, 0, nullptr, nullptr);
        clFinish(queue_);
        clReleaseMemObject(m);
      }
      owned_.erase(owned_.begin() + static_cast<std::ptrdiff_t>(k));
      return true;
    }
  return false;
}

bool Context::is_pinned(const void* p, std::size_t bytes) const {
  const char* c = static_cast<const char*>(p);
  for (const PinnedBlock& b : owned_)
    if (c >= b.host && c + bytes <= b.host + b.size) return true;
  return false;
}

_cl_mem* Context::shared_region(const void* p, std::size_t bytes, std::size_t* offset) const {
  const char* c = static_cast<const char*>(p);
  for (const PinnedBlock& b : owned_)
    if (b.shared && c >= b.host && c + bytes <= b.host + b.size) {
      const auto at = static_cast<std::size_t>(c - b.host);
      if (at % sub_align_ != 0) return nullptr;
      *offset = at;
      return static_cast<cl_mem>(b.mem);
    }
  return nullptr;
}

void Context::copy_when_drained(const void* from, void* to, std::size_t bytes) {
  copy_back_.push_back({from, to, bytes});
}

void Context::release_pinned() {
  while (!owned_.empty())
    free_pinned(owned_.back().host);
  for (PinnedBlock& b : pinned_) {
    cl_mem m = static_cast<cl_mem>(b.mem);
    clEnqueueUnmapMemObject(queue_, m, b.host, 0, nullptr, nullptr);
  }
  if (!pinned_.empty()) clFinish(queue_);
  for (PinnedBlock& b : pinned_)
    clReleaseMemObject(static_cast<cl_mem>(b.mem));
  pinned_.clear();
}

void Context::run(Kernel& kernel, std::size_t items, std::size_t group) {
  if (items == 0) return;
  if (group == 0) {
    group = std::max<std::size_t>(1, kernel.preferred_group_size());
    // On a CPU a group is one core's loop over its items: a wave too small to give each core a
    // few groups gets smaller ones (a batch's 29 primaries, each sampling a hemisphere of 1,024
    // rays, in one group of 128 kept one core busy and the others idle).
    if (info_.kind == DeviceKind::CPU)
      while (group > 1 && (items + group - 1) / group < 4 * std::size_t{info_.compute_units})
        group /= 2;
  }
  std::size_t global = (items + group - 1) / group * group;
  RADCL_CL(clEnqueueNDRangeKernel(queue_, kernel.handle(), 1, nullptr, &global, &group, 0, nullptr,
                                  nullptr));
  pending_ = true;
}

void Context::finish() {
  RADCL_CL(clFinish(queue_));
  note_wait();
  pending_ = false;
  drained();
}

Context::Mark Context::mark() {
  Mark m;
  cl_event e = nullptr;
  RADCL_CL(clEnqueueMarkerWithWaitList(queue_, 0, nullptr, &e));
  m.event = e;
  m.copies = copy_back_.size();
  return m;
}

void Context::wait_for(Mark& m) {
  if (!m.event) return;
  cl_event e = static_cast<cl_event>(m.event);
  m.event = nullptr;
  clFlush(queue_); // the commands after the mark start too
  const cl_int st = clWaitForEvents(1, &e);
  clReleaseEvent(e);
  RADCL_CL(st);
  note_wait();
  // The reads before the mark have landed in their pinned room: to their destinations.
  const std::size_t k = std::min(m.copies, copy_back_.size());
  for (std::size_t i = 0; i < k; ++i)
    parallel_copy(copy_back_[i].to, copy_back_[i].from, copy_back_[i].bytes);
  copy_back_.erase(copy_back_.begin(), copy_back_.begin() + static_cast<std::ptrdiff_t>(k));
}

const void* Context::stage(const void* src, std::size_t bytes) {
  if (void* p = pinned(bytes)) {
    parallel_copy(p, src, bytes);
    return p;
  }
  std::vector<char> b;
  if (!spare_.empty()) {
    b = std::move(spare_.back());
    spare_.pop_back();
  }
  b.assign(static_cast<const char*>(src), static_cast<const char*>(src) + bytes);
  staged_.push_back(std::move(b));
  return staged_.back().data();
}

void Context::drained() {
  for (const CopyBack& c : copy_back_)
    parallel_copy(c.to, c.from, c.bytes);
  copy_back_.clear();
  for (PinnedBlock& b : pinned_)
    b.used = 0;
  pin_block_ = 0;
  // Keep a few blocks (their memory is already mapped) for the next transfers.
  for (auto& b : staged_)
    if (spare_.size() < 16) spare_.push_back(std::move(b));
  staged_.clear();
}

void Context::sync() {
  if (pending_) finish();
}

Context& default_context() {
  static std::once_flag once;
  static std::unique_ptr<Context> ctx;
  std::call_once(once, [] { ctx = std::make_unique<Context>(select_device()); });
  return *ctx;
}

std::future<void> start_default_context() {
  return std::async(std::launch::async, [] {
    try {
      default_context();
    } catch (...) { // reported by the call that needs the device
    }
  });
}

} // namespace radcl::device
