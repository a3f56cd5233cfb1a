// RADCL_DEVICE: index, name substring, default preference (GPU, then CPU), and clear errors.
#include <gtest/gtest.h>

#include "radcl/device/device_info.h"
#include "radcl/util/error.h"

using namespace radcl::device;

namespace {
std::vector<DeviceInfo> fake() {
  std::vector<DeviceInfo> v(3);
  v[0].index = 0, v[0].name = "pthread-skylake", v[0].platform_name = "Portable Computing Language",
  v[0].kind = DeviceKind::CPU;
  v[1].index = 1, v[1].name = "NVIDIA H100 80GB HBM3", v[1].platform_name = "NVIDIA CUDA",
  v[1].kind = DeviceKind::GPU;
  v[2].index = 2, v[2].name = "Other", v[2].vendor = "ACME", v[2].kind = DeviceKind::Other;
  v[0].device_version = "OpenCL 3.0 PoCL HSTR: cpu-x86_64";
  return v;
}
} // namespace

TEST(DeviceSelection, DefaultPrefersGpuThenCpu) {
  auto v = fake();
  EXPECT_EQ(select_device(v, "").index, 1);
  v.erase(v.begin() + 1);
  EXPECT_EQ(select_device(v, "").index, 0);
}

TEST(DeviceSelection, ByIndexAndCaseInsensitiveName) {
  auto v = fake();
  EXPECT_EQ(select_device(v, "0").index, 0);
  EXPECT_EQ(select_device(v, "2").index, 2);
  EXPECT_EQ(select_device(v, "h100").index, 1);
  EXPECT_EQ(select_device(v, "portable").index, 0);
  EXPECT_EQ(select_device(v, "acme").index, 2);
  EXPECT_EQ(select_device(v, "pocl").index, 0);
}

TEST(DeviceSelection, ErrorsAreFatal) {
  auto v = fake();
  EXPECT_THROW(select_device(v, "7"), radcl::FatalError);
  EXPECT_THROW(select_device(v, "-1"), radcl::FatalError);
  EXPECT_THROW(select_device(v, "tpu"), radcl::FatalError);
  EXPECT_THROW(select_device({}, ""), radcl::FatalError);
}

TEST(DeviceSelection, RealEnumerationFindsADevice) {
  auto v = enumerate_devices();
  ASSERT_FALSE(v.empty()) << "no OpenCL device: install pocl-opencl-icd";
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(v[i].index, static_cast<int>(i));
    EXPECT_FALSE(v[i].name.empty());
    EXPECT_GT(v[i].compute_units, 0u);
    EXPECT_GT(v[i].max_work_group, 0u);
  }
}
