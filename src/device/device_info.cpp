#include "radcl/device/device_info.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "radcl/device/cl.h"
#include "radcl/device/icd_choice.h"
#include "radcl/util/error.h"

namespace radcl::device {
namespace {

std::string platform_string(cl_platform_id p, cl_platform_info what) {
  size_t n = 0;
  RADCL_CL(clGetPlatformInfo(p, what, 0, nullptr, &n));
  std::string s(n, '\0');
  RADCL_CL(clGetPlatformInfo(p, what, n, s.data(), nullptr));
  while (!s.empty() && (s.back() == '\0' || s.back() == ' '))
    s.pop_back();
  return s;
}

std::string device_string(cl_device_id d, cl_device_info what) {
  size_t n = 0;
  RADCL_CL(clGetDeviceInfo(d, what, 0, nullptr, &n));
  std::string s(n, '\0');
  RADCL_CL(clGetDeviceInfo(d, what, n, s.data(), nullptr));
  while (!s.empty() && (s.back() == '\0' || s.back() == ' '))
    s.pop_back();
  return s;
}

template <class T> T device_value(cl_device_id d, cl_device_info what) {
  T v{};
  RADCL_CL(clGetDeviceInfo(d, what, sizeof v, &v, nullptr));
  return v;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

} // namespace

const char* kind_name(DeviceKind k) {
  switch (k) {
  case DeviceKind::CPU:
    return "CPU";
  case DeviceKind::GPU:
    return "GPU";
  case DeviceKind::Accelerator:
    return "accelerator";
  default:
    return "other";
  }
}

std::vector<DeviceInfo> enumerate_devices() {
  // PoCL links kernels with the system's `ld`, found on PATH: a program started with an empty
  // environment (env -i, some job schedulers) would abort inside the driver. Give it the
  // search path a shell would use.
  ::setenv("PATH", "/usr/local/bin:/usr/bin:/bin", 0);
  cl_uint np = 0;
  cl_int st = clGetPlatformIDs(0, nullptr, &np);
  if (st == -1001 /* CL_PLATFORM_NOT_FOUND_KHR: the ICD loader found no vendor */ || np == 0)
    return {};
  RADCL_CL(st);
  std::vector<cl_platform_id> platforms(np);
  RADCL_CL(clGetPlatformIDs(np, platforms.data(), nullptr));

  std::vector<DeviceInfo> out;
  for (cl_platform_id p : platforms) {
    cl_uint nd = 0;
    st = clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, 0, nullptr, &nd);
    if (st == CL_DEVICE_NOT_FOUND || nd == 0) continue;
    RADCL_CL(st);
    std::vector<cl_device_id> ids(nd);
    RADCL_CL(clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, nd, ids.data(), nullptr));
    for (cl_device_id d : ids) {
      DeviceInfo info;
      info.index = static_cast<int>(out.size());
      info.platform = p;
      info.id = d;
      info.platform_name = platform_string(p, CL_PLATFORM_NAME);
      info.platform_version = platform_string(p, CL_PLATFORM_VERSION);
      info.name = device_string(d, CL_DEVICE_NAME);
      info.vendor = device_string(d, CL_DEVICE_VENDOR);
      info.device_version = device_string(d, CL_DEVICE_VERSION);
      info.driver_version = device_string(d, CL_DRIVER_VERSION);
      info.opencl_c_version = device_string(d, CL_DEVICE_OPENCL_C_VERSION);
      auto type = device_value<cl_device_type>(d, CL_DEVICE_TYPE);
      info.kind = (type & CL_DEVICE_TYPE_GPU)           ? DeviceKind::GPU
                  : (type & CL_DEVICE_TYPE_CPU)         ? DeviceKind::CPU
                  : (type & CL_DEVICE_TYPE_ACCELERATOR) ? DeviceKind::Accelerator
                                                        : DeviceKind::Other;
      info.compute_units = device_value<cl_uint>(d, CL_DEVICE_MAX_COMPUTE_UNITS);
      info.clock_mhz = device_value<cl_uint>(d, CL_DEVICE_MAX_CLOCK_FREQUENCY);
      info.global_mem = device_value<cl_ulong>(d, CL_DEVICE_GLOBAL_MEM_SIZE);
      info.local_mem = device_value<cl_ulong>(d, CL_DEVICE_LOCAL_MEM_SIZE);
      info.max_alloc = device_value<cl_ulong>(d, CL_DEVICE_MAX_MEM_ALLOC_SIZE);
      info.max_work_group = device_value<size_t>(d, CL_DEVICE_MAX_WORK_GROUP_SIZE);
      // Deprecated in 2.0 but still answered by every driver we target; a CPU device shares
      // host memory whatever it says.
      info.host_unified_memory =
          device_value<cl_bool>(d, CL_DEVICE_HOST_UNIFIED_MEMORY) || info.kind == DeviceKind::CPU;
      info.available = device_value<cl_bool>(d, CL_DEVICE_AVAILABLE);
      out.push_back(std::move(info));
    }
  }
  return out;
}

DeviceInfo select_device(const std::vector<DeviceInfo>& devices, const std::string& spec) {
  if (devices.empty())
    throw FatalError("no OpenCL device found (is an ICD such as pocl-opencl-icd installed? "
                     "OCL_ICD_VENDORS may point elsewhere)");
  if (!spec.empty()) {
    char* end = nullptr;
    long idx = std::strtol(spec.c_str(), &end, 10);
    if (end && *end == '\0') {
      if (idx < 0 || idx >= static_cast<long>(devices.size()))
        throw FatalError("RADCL_DEVICE=" + spec + ": no device with that index (there are " +
                         std::to_string(devices.size()) + ")");
      return devices[idx];
    }
    std::string want = lower(spec);
    for (const DeviceInfo& d : devices)
      for (const std::string* field :
           {&d.name, &d.vendor, &d.platform_name, &d.platform_version, &d.device_version})
        if (lower(*field).find(want) != std::string::npos) return d;
    throw FatalError("RADCL_DEVICE=" + spec + ": no device matches (see radcl devices)");
  }
  for (DeviceKind k : {DeviceKind::GPU, DeviceKind::CPU})
    for (const DeviceInfo& d : devices)
      if (d.kind == k && d.available) return d;
  return devices.front();
}

DeviceInfo select_device() {
  load_only_named_driver();
  const char* spec = std::getenv("RADCL_DEVICE");
  return select_device(enumerate_devices(), spec ? spec : "");
}

} // namespace radcl::device
