// Host and device agree on every shared struct's size and field offsets.
#include <cstddef>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "device_fixture.h"
#include "radcl/device/self_check.h"
#include "radcl/device_types.h"

using namespace radcl::device;

TEST(Layout, HostAndDeviceAgree) {
  Context& ctx = test_context();
  std::vector<std::string> bad = check_layout(ctx);
  for (const std::string& b : bad)
    ADD_FAILURE() << b << " on " << ctx.info().name;
}

TEST(Layout, StructsAreSixteenByteMultiples) {
  EXPECT_EQ(sizeof(rc_float4), 16u);
  EXPECT_EQ(sizeof(rc_ray) % 16, 0u);
  EXPECT_EQ(sizeof(rc_hit) % 16, 0u);
  EXPECT_EQ(sizeof(rc_shadow) % 16, 0u);
  EXPECT_EQ(sizeof(rc_surface) % 16, 0u);
  EXPECT_EQ(sizeof(rc_material) % 16, 0u);
  EXPECT_EQ(sizeof(rc_source) % 16, 0u);
  EXPECT_EQ(sizeof(rc_rng_key), 16u);
}

// The wave buffers' per-ray cost: rc_ray carries the ray tree's length before its origin
// (patterns' T), which took it from 96 to 112 bytes; rc_shadow keeps its size.
TEST(Layout, RayAndShadowSizes) {
  EXPECT_EQ(sizeof(rc_ray), 112u);
  EXPECT_EQ(offsetof(rc_ray, dist0), 96u);
  EXPECT_EQ(sizeof(rc_shadow), 96u);
}
