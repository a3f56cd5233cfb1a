// Host and device agree on every shared struct's size and field offsets.
#include <cstddef>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "device_fixture.h"
#include "radcl/device/buffer.h"
#include "radcl/device/program.h"
#include "radcl/device_types.h"

using namespace radcl::device;

TEST(Layout, HostAndDeviceAgree) {
  std::vector<std::size_t> host;
  std::vector<std::string> what;
#define RC_SIZE(T)                                                                                 \
  host.push_back(sizeof(T));                                                                       \
  what.push_back("sizeof(" #T ")");
#define RC_FIELD(T, f)                                                                             \
  host.push_back(offsetof(T, f));                                                                  \
  what.push_back("offsetof(" #T ", " #f ")");
  RADCL_LAYOUT_STRUCTS(RC_SIZE)
  RADCL_LAYOUT_FIELDS(RC_FIELD)
#undef RC_SIZE
#undef RC_FIELD

  Context& ctx = test_context();
  Program prog(ctx, ProgramSource{{"probe/layout.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_layout");
  Buffer out(ctx, host.size() * sizeof(std::uint64_t));
  std::vector<std::uint64_t> init(host.size(), ~0ull);
  out.write(init.data(), init.size() * 8);
  k.arg(0, out).arg(1, static_cast<std::uint32_t>(host.size()));
  ctx.run(k, 1);
  auto dev = out.to_vector<std::uint64_t>(host.size());
  for (std::size_t i = 0; i < host.size(); ++i)
    EXPECT_EQ(dev[i], host[i]) << what[i] << " on " << ctx.info().name;
}

TEST(Layout, StructsAreSixteenByteMultiples) {
  EXPECT_EQ(sizeof(rc_float4), 16u);
  EXPECT_EQ(sizeof(rc_ray) % 16, 0u);
  EXPECT_EQ(sizeof(rc_hit) % 16, 0u);
  EXPECT_EQ(sizeof(rc_shadow) % 16, 0u);
  EXPECT_EQ(sizeof(rc_rng_key), 16u);
}
