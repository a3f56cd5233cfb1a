// OpenCL platforms and devices: enumeration and the choice radcl makes (RADCL_DEVICE).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radcl::device {

enum class DeviceKind { CPU, GPU, Accelerator, Other };

struct DeviceInfo {
  int index = 0;            // position in enumerate_devices(): what RADCL_DEVICE=<n> selects
  void* platform = nullptr; // cl_platform_id
  void* id = nullptr;       // cl_device_id
  std::string platform_name, platform_version;
  std::string name, vendor, device_version, driver_version, opencl_c_version;
  DeviceKind kind = DeviceKind::Other;
  std::uint32_t compute_units = 0, clock_mhz = 0;
  std::uint64_t global_mem = 0, local_mem = 0, max_alloc = 0;
  std::size_t max_work_group = 0;
  bool host_unified_memory = false; // memory is the host's: buffers are zero-copy
  bool available = true;
};

const char* kind_name(DeviceKind k);

// Every device of every platform, in platform order. No platform is not an error here.
std::vector<DeviceInfo> enumerate_devices();

// RADCL_DEVICE selects by index or by a case-insensitive substring of the device name, vendor,
// platform name or version strings (so "pocl" finds PoCL whatever the CPU is called); without it
// the first GPU, else the first CPU, else the first device. Throws FatalError when nothing matches
// or there is no OpenCL device at all.
DeviceInfo select_device(const std::vector<DeviceInfo>& devices, const std::string& spec);
DeviceInfo select_device(); // from the environment

} // namespace radcl::device
