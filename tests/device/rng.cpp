// The counter-based generator: known answers, uniformity, independence across every key field,
// and bit-identical values on host and device.
#include <array>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <vector>

#include "device_fixture.h"
#include "radcl/device/self_check.h"
#include "radcl/rng.h"

using namespace radcl::device;

namespace {

rc_u32x4 philox(std::array<rc_u32, 4> c, rc_u32 k0, rc_u32 k1) {
  rc_u32x4 v{{c[0], c[1], c[2], c[3]}};
  return rc_philox4x32(v, k0, k1);
}

// Chi-square critical value for 255 degrees of freedom at p = 0.001.
constexpr double kChi2Crit255 = 330.5;

double chi2_1d(const std::function<float(std::uint32_t)>& sample, std::uint32_t n) {
  std::vector<double> bins(256, 0.0);
  for (std::uint32_t i = 0; i < n; ++i) {
    float u = sample(i);
    EXPECT_GE(u, 0.0f);
    EXPECT_LT(u, 1.0f);
    bins[static_cast<int>(u * 256)] += 1;
  }
  double e = n / 256.0, chi2 = 0;
  for (double b : bins)
    chi2 += (b - e) * (b - e) / e;
  return chi2;
}

// Joint distribution of two streams on a 16x16 grid: independent uniform streams fill it evenly.
double chi2_pairs(const std::function<std::pair<float, float>(std::uint32_t)>& sample,
                  std::uint32_t n) {
  std::vector<double> bins(256, 0.0);
  for (std::uint32_t i = 0; i < n; ++i) {
    auto [a, b] = sample(i);
    bins[static_cast<int>(a * 16) * 16 + static_cast<int>(b * 16)] += 1;
  }
  double e = n / 256.0, chi2 = 0;
  for (double b : bins)
    chi2 += (b - e) * (b - e) / e;
  return chi2;
}

double correlation(const std::function<std::pair<float, float>(std::uint32_t)>& sample,
                   std::uint32_t n) {
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    auto [a, b] = sample(i);
    sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b;
  }
  double ca = saa / n - (sa / n) * (sa / n), cb = sbb / n - (sb / n) * (sb / n);
  return (sab / n - (sa / n) * (sb / n)) / std::sqrt(ca * cb);
}

constexpr std::uint32_t kN = 1u << 20;

} // namespace

// Known-answer vectors of Philox4x32-10 published with Random123.
TEST(Rng, PhiloxKnownAnswers) {
  rc_u32x4 a = philox({0, 0, 0, 0}, 0, 0);
  EXPECT_EQ(a.v[0], 0x6627e8d5u);
  EXPECT_EQ(a.v[1], 0xe169c58du);
  EXPECT_EQ(a.v[2], 0xbc57ac4cu);
  EXPECT_EQ(a.v[3], 0x9b00dbd8u);
  rc_u32x4 b = philox({~0u, ~0u, ~0u, ~0u}, ~0u, ~0u);
  EXPECT_EQ(b.v[0], 0x408f276du);
  EXPECT_EQ(b.v[1], 0x41c83b0eu);
  EXPECT_EQ(b.v[2], 0xa20bc7c6u);
  EXPECT_EQ(b.v[3], 0x6d5451fdu);
  rc_u32x4 c =
      philox({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}, 0xa4093822u, 0x299f31d0u);
  EXPECT_EQ(c.v[0], 0xd16cfe09u);
  EXPECT_EQ(c.v[1], 0x94fdccebu);
  EXPECT_EQ(c.v[2], 0x5001e420u);
  EXPECT_EQ(c.v[3], 0x24126ea1u);
}

TEST(Rng, UniformOverEachKeyField) {
  EXPECT_LT(chi2_1d([](std::uint32_t i) { return rc_random(rc_make_key(i, 0, 0, 1), 0); }, kN),
            kChi2Crit255);
  EXPECT_LT(chi2_1d([](std::uint32_t i) { return rc_random(rc_make_key(7, i, 0, 1), 0); }, kN),
            kChi2Crit255);
  EXPECT_LT(chi2_1d([](std::uint32_t i) { return rc_random(rc_make_key(7, 3, i, 1), 0); }, kN),
            kChi2Crit255);
  EXPECT_LT(chi2_1d([](std::uint32_t i) { return rc_random(rc_make_key(7, 3, 2, i), 0); }, kN),
            kChi2Crit255);
  EXPECT_LT(chi2_1d([](std::uint32_t i) { return rc_random(rc_make_key(7, 3, 2, 1), i); }, kN),
            kChi2Crit255);
}

TEST(Rng, IndependentAcrossNeighbouringKeys) {
  using P = std::pair<float, float>;
  std::vector<std::function<P(std::uint32_t)>> pairs = {
      // adjacent primary rays
      [](std::uint32_t i) {
        return P{rc_random(rc_make_key(i, 0, 0, 9), 0), rc_random(rc_make_key(i + 1, 0, 0, 9), 0)};
      },
      // adjacent samples of one ray
      [](std::uint32_t i) {
        return P{rc_random(rc_make_key(5, i, 1, 9), 0), rc_random(rc_make_key(5, i + 1, 1, 9), 0)};
      },
      // parent and child depth
      [](std::uint32_t i) {
        return P{rc_random(rc_make_key(i, 2, 0, 9), 1), rc_random(rc_make_key(i, 2, 1, 9), 1)};
      },
      // consecutive seeds (-u+ runs)
      [](std::uint32_t i) {
        return P{rc_random(rc_make_key(i, 0, 0, 9), 0), rc_random(rc_make_key(i, 0, 0, 10), 0)};
      },
      // two dimensions of one key, within and across 4-value blocks
      [](std::uint32_t i) {
        return P{rc_random(rc_make_key(i, 0, 0, 9), 0), rc_random(rc_make_key(i, 0, 0, 9), 1)};
      },
      [](std::uint32_t i) {
        return P{rc_random(rc_make_key(i, 0, 0, 9), 3), rc_random(rc_make_key(i, 0, 0, 9), 4)};
      },
  };
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    EXPECT_LT(chi2_pairs(pairs[p], kN), kChi2Crit255) << "pair " << p;
    // Standard error of r for 2^20 samples is ~0.001.
    EXPECT_LT(std::fabs(correlation(pairs[p], kN)), 0.005) << "pair " << p;
  }
}

TEST(Rng, DeviceMatchesHostBitForBit) {
  Context& ctx = test_context();
  // An item count that is no multiple of any work-group size, and dimensions across blocks.
  std::vector<std::string> bad = check_rng(ctx, 10007, 9, 0xC0FFEE);
  for (const std::string& b : bad)
    ADD_FAILURE() << b << " on " << ctx.info().name;
}
