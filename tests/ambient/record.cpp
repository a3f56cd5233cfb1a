// The record's pieces: the 32-bit direction code, the 67-byte layout and the validity rules
// Radiance applies when reading (ambient-file.md §1.2, §1.3, §2).
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <random>

#include "radcl/ambient/dircode.h"
#include "radcl/ambient/record.h"

using namespace radcl::ambient;

namespace {

AmbientRecord sample_record() {
  AmbientRecord r;
  r.pos = {1.5f, -2.25f, 3.0f};
  r.ndir = encode_dir({0.0, 0.0, 1.0});
  r.udir = encode_dir({1.0, 0.0, 0.0});
  r.lvl = 2;
  r.weight = 0.25f;
  r.rad = {0.5f, 0.75f};
  r.val = {1.5f, 0.75f, 0.25f}; // exact RGBE codes: survives encoding unchanged
  r.gpos = {0.125f, -0.5f};
  r.gdir = {-1.0f, 2.0f};
  r.corral = 0x80000001u;
  return r;
}

double angle_deg(const Dir& a, const Dir& b) {
  const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(std::min(1.0, d)) * 180.0 / M_PI;
}

} // namespace

TEST(DirCode, KnownCodes) {
  EXPECT_EQ(encode_dir({0.0, 0.0, 1.0}), 0x00000008);
  EXPECT_EQ(encode_dir({0.0, 0.0, 0.0}), 0);
  const Dir z = decode_dir(0x00000008);
  EXPECT_EQ(z[0], 0.0);
  EXPECT_EQ(z[1], 0.0);
  EXPECT_EQ(z[2], 1.0);
  const Dir zero = decode_dir(0);
  EXPECT_EQ(zero[0], 0.0);
  EXPECT_EQ(zero[1], 0.0);
  EXPECT_EQ(zero[2], 0.0);
  // -x: sign bit 0, x is the dropped (largest) component: F2Z set, field 1 holds y.
  const std::int32_t mx = encode_dir({-1.0, 0.0, 0.0});
  EXPECT_EQ(mx, 0x01 | 0x10);
  const Dir d = decode_dir(mx);
  EXPECT_EQ(d[0], -1.0);
  // A tiny negative component rounds to 0 but keeps its sign bit: Radiance prints -0.000000.
  const Dir n = decode_dir(encode_dir({1e-7, -1e-7, 1.0}));
  EXPECT_TRUE(std::signbit(n[1]));
  EXPECT_FALSE(std::signbit(n[0]));
}

// Found by fuzz_amb_reader (lookamb -r text): components outside [-1, 1] overflowed the
// conversion to int. They are clamped: the result is the code of the clamped vector.
TEST(DirCode, OutOfRangeComponentsAreClamped) {
  EXPECT_EQ(encode_dir({0.0, 0.0, 4.9e13}), encode_dir({0.0, 0.0, 1.0}));
  EXPECT_EQ(encode_dir({-1e300, 0.0, 0.0}), encode_dir({-1.0, 0.0, 0.0}));
  EXPECT_EQ(encode_dir({std::nan(""), 0.0, 1.0}), encode_dir({0.0, 0.0, 1.0}));
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(encode_dir({0.5, -inf, 0.5}), encode_dir({0.5, -1.0, 0.5}));
}

TEST(DirCode, AccuracyOverTheSphere) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  double worst = 0.0, sum = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    Dir v{g(rng), g(rng), g(rng)};
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (double& c : v)
      c /= len;
    const std::int32_t code = encode_dir(v);
    ASSERT_NE(code, 0);
    ASSERT_EQ(code & 0x80000000u, 0u);
    const double a = angle_deg(v, decode_dir(code));
    worst = std::max(worst, a);
    sum += a;
    const Dir d = decode_dir(code);
    ASSERT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1.0, 1e-12);
  }
  // dircode.c's comment: mean 0.0022 degrees, maximum 0.0058 degrees.
  EXPECT_LT(sum / n, 0.0030);
  EXPECT_LT(worst, 0.0060);
}

TEST(Record, LayoutIs67BigEndianBytes) {
  const AmbientRecord r = sample_record();
  const RecordBytes b = encode_record(r);
  EXPECT_EQ(b[0], 2); // level
  // weight 0.25 = 0.5 * 2^-1: mantissa 0.5 * 0x7fffffff = 0x3fffffff, exponent -1.
  const unsigned char weight[5] = {0x3f, 0xff, 0xff, 0xff, 0xff};
  EXPECT_EQ(std::memcmp(&b[1], weight, 5), 0);
  const unsigned char ndir[4] = {0, 0, 0, 8}; // +z at offset 21
  EXPECT_EQ(std::memcmp(&b[21], ndir, 4), 0);
  // val at 29: max 1.5 = 0.75 * 2^1 -> E = 129, R = 1.5 * 128 = 192, G = 96, B = 32.
  const unsigned char val[4] = {192, 96, 32, 129};
  EXPECT_EQ(std::memcmp(&b[29], val, 4), 0);
  const unsigned char corral[4] = {0x80, 0, 0, 1}; // at 63
  EXPECT_EQ(std::memcmp(&b[63], corral, 4), 0);
  // The RGBE value decodes to the centre of its code interval.
  const AmbientRecord back = decode_record(b.data());
  EXPECT_FLOAT_EQ(back.val[0], 192.5f / 128);
  EXPECT_FLOAT_EQ(back.val[1], 96.5f / 128);
  EXPECT_EQ(back.pos, r.pos);
  EXPECT_EQ(back.weight, r.weight);
  EXPECT_EQ(back.rad, r.rad);
  EXPECT_EQ(back.gpos, r.gpos);
  EXPECT_EQ(back.gdir, r.gdir);
  EXPECT_EQ(back.ndir, r.ndir);
  EXPECT_EQ(back.udir, r.udir);
  EXPECT_EQ(back.corral, r.corral);
  EXPECT_EQ(back.lvl, r.lvl);
  // Decoding and encoding again reproduces the bytes.
  EXPECT_EQ(encode_record(back), b);
}

TEST(Record, LevelIsOneUnsignedByte) {
  AmbientRecord r = sample_record();
  r.lvl = 255;
  EXPECT_EQ(decode_record(encode_record(r).data()).lvl, 255);
  r.lvl = 257; // writambval writes the low byte
  EXPECT_EQ(decode_record(encode_record(r).data()).lvl, 1);
}

TEST(Record, ValidityRules) {
  const AmbientRecord good = sample_record();
  EXPECT_TRUE(record_ok(good));
  auto fails = [&](auto change) {
    AmbientRecord r = good;
    change(r);
    return !record_ok(r);
  };
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.pos[1] = 2e10f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.pos[2] = -2e10f; }));
  EXPECT_FALSE(fails([](AmbientRecord& r) { r.pos[0] = 1e10f; })); // the bound is inclusive
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.ndir = 0; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.udir = 0; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.weight = 0.0f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.weight = 1.0001f; }));
  EXPECT_FALSE(fails([](AmbientRecord& r) { r.weight = 1.0f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.rad[0] = 0.0f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.rad[1] = 1e10f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.rad = {0.8f, 0.75f}; }));   // rad0 > rad1
  EXPECT_FALSE(fails([](AmbientRecord& r) { r.rad = {0.75f, 0.75f}; })); // equal is fine
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.val[1] = -0.5f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.val[2] = 1e10f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.gpos[0] = 1e11f; }));
  EXPECT_TRUE(fails([](AmbientRecord& r) { r.gdir[1] = -1e11f; }));
}

TEST(Record, ReadStopsAtShortOrInvalidRecords) {
  const RecordBytes b = encode_record(sample_record());
  EXPECT_TRUE(read_record(b.data(), b.size()).has_value());
  EXPECT_FALSE(read_record(b.data(), b.size() - 1).has_value());
  RecordBytes bad = b;
  std::memset(&bad[21], 0, 4); // ndir = 0
  EXPECT_FALSE(read_record(bad.data(), bad.size()).has_value());
}

TEST(Record, OnlyWhatAReaderAcceptsIsWritable) {
  AmbientRecord r = sample_record();
  EXPECT_TRUE(record_writable(r));
  r.val[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(record_writable(r));
  r = sample_record();
  r.gpos[0] = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(record_writable(r));
  r = sample_record();
  r.weight = 1.5f;
  EXPECT_FALSE(record_writable(r));
  // A direction too short to encode becomes code 0, which a reader rejects.
  r = sample_record();
  r.ndir = encode_dir({1e-6, 0.0, 0.0});
  EXPECT_FALSE(record_writable(r));
}
