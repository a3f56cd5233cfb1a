// An OpenCL context and in-order queue on one device, with kernel launches.
#pragma once

#include <cstddef>
#include <memory>

#include "radcl/device/device_info.h"

struct _cl_context;
struct _cl_command_queue;

namespace radcl::device {

class Kernel;

class Context {
public:
  explicit Context(const DeviceInfo& device);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceInfo& info() const { return info_; }
  bool zero_copy() const { return info_.host_unified_memory; }

  // Runs `kernel` over `items` work-items. The global size is rounded up to a multiple of the
  // work-group size (PoCL requires it), so every kernel bounds-checks its index against a count
  // argument. group = 0 picks the kernel's preferred multiple.
  void run(Kernel& kernel, std::size_t items, std::size_t group = 0);
  void finish();

  _cl_context* handle() const { return context_; }
  _cl_command_queue* queue() const { return queue_; }

private:
  DeviceInfo info_;
  _cl_context* context_ = nullptr;
  _cl_command_queue* queue_ = nullptr;
};

// The device chosen by RADCL_DEVICE (see select_device), shared by the whole process.
Context& default_context();

} // namespace radcl::device
