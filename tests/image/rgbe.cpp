// RGBE conversion: Radiance's setcolr()/colr_color() arithmetic (picture-format.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "radcl/image/rgbe.h"

using namespace radcl::image;

TEST(Rgbe, SpecExample) {
  EXPECT_EQ(to_rgbe(1.0, 0.5, 0.25), (Rgbe{128, 64, 32, 129}));
  // colr_color() returns the centre of each code's interval: (m + 0.5) * 2^(E - 136).
  const Color c = to_color({128, 64, 32, 129});
  EXPECT_EQ(c[0], 128.5f / 128);
  EXPECT_EQ(c[1], 64.5f / 128);
  EXPECT_EQ(c[2], 32.5f / 128);
}

TEST(Rgbe, TruncatesRatherThanRounds) {
  // 0.999 = 0.999 * 2^0: mantissa 0.999 * 256 = 255.74 -> 255, exponent 128.
  EXPECT_EQ(to_rgbe(0.999, 0.0, 0.0), (Rgbe{255, 0, 0, 128}));
  // The smaller channels share the largest one's exponent and lose their low bits.
  EXPECT_EQ(to_rgbe(3.0, 0.01, 2.99), (Rgbe{192, 0, 191, 130}));
}

TEST(Rgbe, BlackNegativeAndTiny) {
  EXPECT_EQ(to_rgbe(0, 0, 0), (Rgbe{0, 0, 0, 0}));
  EXPECT_EQ(to_rgbe(1e-33, 1e-40, 0), (Rgbe{0, 0, 0, 0}));
  EXPECT_EQ(to_rgbe(-1, -2, -3), (Rgbe{0, 0, 0, 0}));
  EXPECT_EQ(to_rgbe(-1.0, 0.5, 0.0), (Rgbe{0, 128, 0, 128}));
  // E = 0 decodes to black whatever the mantissas.
  EXPECT_EQ(to_color({200, 100, 50, 0}), (Color{0, 0, 0}));
}

TEST(Rgbe, ExactPowersOfTwo) {
  for (int e = -100; e <= 100; ++e) {
    const double v = std::ldexp(1.0, e);
    EXPECT_EQ(to_rgbe(v, v, v), (Rgbe{128, 128, 128, static_cast<std::uint8_t>(129 + e)}));
  }
}

// Every normalised code (largest mantissa >= 128) decodes to a value that encodes back to itself,
// over the exponents whose values float holds exactly and setcolr() does not call black.
TEST(Rgbe, CodesRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int e = 24; e <= 255; ++e) {
    for (int m = 128; m <= 255; ++m) {
      const int slot = byte(rng) % 3;
      Rgbe p{};
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<std::uint8_t>(byte(rng) % (m + 1));
      p[slot] = static_cast<std::uint8_t>(m);
      p[3] = static_cast<std::uint8_t>(e);
      ASSERT_EQ(to_rgbe(to_color(p)), p)
          << int(p[0]) << " " << int(p[1]) << " " << int(p[2]) << " " << e;
    }
  }
}

// Values survive within one code of the largest channel.
TEST(Rgbe, ValuesRoundTripWithinOneCode) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> mant(0.0, 1.0);
  std::uniform_int_distribution<int> exp(-30, 30);
  for (int i = 0; i < 100000; ++i) {
    const double s = std::ldexp(1.0, exp(rng));
    const double v[3] = {mant(rng) * s, mant(rng) * s, mant(rng) * s};
    const Color c = to_color(to_rgbe(v[0], v[1], v[2]));
    const double top = std::max({v[0], v[1], v[2]});
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(c[k], v[k], top / 128 + 1e-30);
  }
}

// Found by fuzz_amb_reader (an infinite value in lookamb -r text): frexp(inf) made the scale
// NaN and its conversion to int undefined. Non-finite maxima now have fixed codes.
TEST(Rgbe, NonFiniteValuesHaveFixedCodes) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(to_rgbe(inf, 1.0, -inf), (Rgbe{255, 0, 0, 255}));
  EXPECT_EQ(to_rgbe(nan, nan, nan), (Rgbe{0, 0, 0, 0}));
  EXPECT_EQ(to_rgbe(nan, 1.0, 0.5), to_rgbe(0.0, 1.0, 0.5)); // NaN channel next to finite ones
}
