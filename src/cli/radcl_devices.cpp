// radcl devices: every OpenCL device with the properties that matter to radcl, and which one
// RADCL_DEVICE (or the default rule) selects.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "radcl/device/context.h"
#include "radcl/device/device_info.h"
#include "radcl/device/self_check.h"
#include "radcl/util/error.h"
#include "radcl_commands.h"

namespace radcl::cli {
namespace {
std::string mib(std::uint64_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

// Builds the probe programs on `d` and compares struct layouts and random numbers with the host.
bool self_check(const device::DeviceInfo& d) {
  device::Context ctx(d);
  bool ok = true;
  auto report = [&](const char* what, const std::vector<std::string>& bad) {
    std::printf("     check          %s: %s\n", what, bad.empty() ? "ok" : "FAILED");
    for (const std::string& b : bad)
      std::printf("                    %s\n", b.c_str());
    ok = ok && bad.empty();
  };
  report("struct layout", device::check_layout(ctx));
  report("random numbers", device::check_rng(ctx, 4099, 8, 12345));
  return ok;
}
} // namespace

int cmd_devices(int argc, char** argv) {
  bool check = false;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--check")
      check = true;
    else
      throw FatalError(std::string("devices: unknown option \"") + argv[i] + "\"");
  }
  auto devices = device::enumerate_devices();
  if (devices.empty()) {
    std::printf("no OpenCL devices\n");
    return 1;
  }
  const char* spec = std::getenv("RADCL_DEVICE");
  int failed = 0;
  int chosen = device::select_device(devices, spec ? spec : "").index;
  for (const device::DeviceInfo& d : devices) {
    std::printf("%c %d: %s [%s]\n", d.index == chosen ? '*' : ' ', d.index, d.name.c_str(),
                device::kind_name(d.kind));
    std::printf("     platform       %s (%s)\n", d.platform_name.c_str(),
                d.platform_version.c_str());
    std::printf("     vendor         %s\n", d.vendor.c_str());
    std::printf("     version        %s, %s, driver %s\n", d.device_version.c_str(),
                d.opencl_c_version.c_str(), d.driver_version.c_str());
    std::printf("     compute units  %u at %u MHz\n", d.compute_units, d.clock_mhz);
    std::printf("     memory         %s global, %s max allocation, %s local\n",
                mib(d.global_mem).c_str(), mib(d.max_alloc).c_str(),
                std::to_string(d.local_mem >> 10).append(" KiB").c_str());
    std::printf("     work group     %zu max\n", d.max_work_group);
    std::printf("     host memory    %s\n",
                d.host_unified_memory ? "shared (zero-copy buffers)" : "separate (transfers)");
    if (!d.available) std::printf("     (not available)\n");
    if (check && d.available && !self_check(d)) ++failed;
  }
  std::printf("* = selected (%s)\n", spec ? ("RADCL_DEVICE=" + std::string(spec)).c_str()
                                          : "default: first GPU, else first CPU");
  return failed ? 1 : 0;
}

} // namespace radcl::cli
