#include "radcl/device/context.h"

#include <cstdlib>
#include <mutex>
#include <string>

#include "radcl/device/cl.h"
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
}

Context::~Context() {
  if (queue_) {
    clFinish(queue_);
    clReleaseCommandQueue(queue_);
  }
  if (context_) clReleaseContext(context_);
}

void Context::run(Kernel& kernel, std::size_t items, std::size_t group) {
  if (items == 0) return;
  if (group == 0) group = kernel.preferred_group_size();
  if (group == 0) group = 1;
  std::size_t global = (items + group - 1) / group * group;
  RADCL_CL(clEnqueueNDRangeKernel(queue_, kernel.handle(), 1, nullptr, &global, &group, 0, nullptr,
                                  nullptr));
  pending_ = true;
}

void Context::finish() {
  RADCL_CL(clFinish(queue_));
  pending_ = false;
  drained();
}

const void* Context::stage(const void* src, std::size_t bytes) {
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
