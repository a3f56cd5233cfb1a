// Scanline encoding: fwritecolrs()'s packet choices byte for byte, and every layout
// freadcolrs() accepts (picture-format.md §5).
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "radcl/image/scanline.h"

using namespace radcl::image;
using Bytes = std::vector<unsigned char>;

namespace {

std::vector<Rgbe> from_planes(const std::array<Bytes, 4>& planes) {
  std::vector<Rgbe> px(planes[0].size());
  for (std::size_t i = 0; i < px.size(); ++i)
    for (int c = 0; c < 4; ++c)
      px[i][c] = planes[c][i];
  return px;
}

Bytes encode(const std::vector<Rgbe>& px) {
  Bytes out;
  encode_scanline(px, out);
  return out;
}

ScanStatus decode(const Bytes& bytes, std::vector<Rgbe>& px) {
  std::stringbuf sb(std::string(bytes.begin(), bytes.end()));
  return decode_scanline(sb, px);
}

// Lines with runs of random lengths, so every packet kind occurs.
std::vector<Rgbe> runny_line(std::mt19937& rng, int len) {
  std::vector<Rgbe> px(len);
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i < len;) {
      const int run = std::uniform_int_distribution<int>(1, 6)(rng) == 1
                          ? std::uniform_int_distribution<int>(1, 300)(rng)
                          : std::uniform_int_distribution<int>(1, 4)(rng);
      // Red >= 128 as in any normalised pixel: flat lines cannot hold R = G = B = 1, which
      // readers take for an old-style repeat marker.
      const auto v = static_cast<unsigned char>(rng() % 4 + (c == 0 ? 128 : 0));
      for (int k = 0; k < run && i < len; ++k)
        px[i++][c] = v;
    }
  }
  return px;
}

} // namespace

TEST(Scanline, PacketsAsRadianceWritesThem) {
  const auto px = from_planes({Bytes{5, 5, 5, 5, 5, 5, 5, 5}, Bytes{1, 2, 3, 4, 5, 6, 7, 8},
                               Bytes{9, 9, 1, 2, 2, 2, 2, 3}, Bytes{7, 7, 7, 0, 0, 0, 0, 0}});
  const Bytes expect = {2,   2, 0,   8,                  // header: length 8
                        136, 5,                          // R: run of 8
                        8,   1, 2,   3, 4,   5, 6, 7, 8, // G: 8 literals
                        3,   9, 9,   1, 132, 2, 1, 3,    // B: literals, run of 4, literal
                        131, 7, 133, 0};                 // E: short run of 3, run of 5
  EXPECT_EQ(encode(px), expect);
}

TEST(Scanline, LongRunsAndLiteralsSplit) {
  Bytes r(300, 9), g(300), b(300, 0), e(300, 128);
  for (int i = 0; i < 300; ++i)
    g[i] = static_cast<unsigned char>(i * 7); // no repeats
  b[0] = b[1] = 4;                            // two equal bytes before a run: a short run of 2
  const Bytes out = encode(from_planes({r, g, b, e}));
  std::size_t at = 4;
  EXPECT_EQ(Bytes(out.begin() + at, out.begin() + at + 6), (Bytes{255, 9, 255, 9, 174, 9}));
  at += 6;
  EXPECT_EQ(out[at], 128); // literals in chunks of at most 128
  at += 129;
  EXPECT_EQ(out[at], 128);
  at += 129;
  EXPECT_EQ(out[at], 44);
  at += 45;
  EXPECT_EQ(Bytes(out.begin() + at, out.begin() + at + 8), (Bytes{130, 4, 255, 0, 255, 0, 172, 0}));
}

TEST(Scanline, ShortAndHugeLinesAreFlat) {
  for (int len : {1, 7, 32768}) {
    std::vector<Rgbe> px(len, Rgbe{10, 20, 30, 130});
    const Bytes out = encode(px);
    ASSERT_EQ(out.size(), 4u * len);
    std::vector<Rgbe> back(len);
    ASSERT_EQ(decode(out, back), ScanStatus::ok);
    EXPECT_EQ(back, px);
  }
}

TEST(Scanline, RandomLinesRoundTrip) {
  std::mt19937 rng(3);
  for (int len : {1, 2, 7, 8, 9, 127, 128, 129, 255, 256, 1000, 32767, 32768}) {
    for (int t = 0; t < 5; ++t) {
      const auto px = runny_line(rng, len);
      std::vector<Rgbe> back(len);
      const Bytes enc = encode(px);
      ASSERT_EQ(decode(enc, back), ScanStatus::ok) << len;
      ASSERT_EQ(back, px) << len;
      // The encoder never writes a literal of 0 or a run shorter than 2.
      if (len >= kMinRleLength && len <= kMaxRleLength) {
        for (std::size_t i = 4; i < enc.size();) {
          const int code = enc[i];
          ASSERT_NE(code, 0);
          ASSERT_NE(code, 129);
          i += code > 128 ? 2 : 1 + code;
        }
      }
    }
  }
}

TEST(Scanline, ReadsFlatPixelsOfRleLength) {
  std::vector<Rgbe> px(10);
  for (int i = 0; i < 10; ++i)
    px[i] = {static_cast<unsigned char>(100 + i), 50, 25, 131};
  px[0] = {2, 200, 5, 130};  // starts like an RLE header, but byte 1 is not 2
  px[1] = {2, 2, 0x80, 130}; // would-be length with its high bit set: still a pixel
  Bytes flat;
  for (const auto& p : px)
    flat.insert(flat.end(), p.begin(), p.end());
  std::vector<Rgbe> back(10);
  ASSERT_EQ(decode(flat, back), ScanStatus::ok);
  EXPECT_EQ(back, px);
  px[0] = {2, 2, 0x80, 130};
  std::copy(px[0].begin(), px[0].end(), flat.begin());
  ASSERT_EQ(decode(flat, back), ScanStatus::ok);
  EXPECT_EQ(back, px);
}

TEST(Scanline, ReadsOldStyleRepeats) {
  // 10 pixels: A, then 3 repeats; B, then 5 repeats.
  const Rgbe a{200, 100, 50, 130}, b{130, 140, 150, 127};
  Bytes bytes = {200, 100, 50, 130, 1, 1, 1, 3, 130, 140, 150, 127, 1, 1, 1, 5};
  std::vector<Rgbe> back(10);
  ASSERT_EQ(decode(bytes, back), ScanStatus::ok);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(back[i], a);
  for (int i = 4; i < 10; ++i)
    EXPECT_EQ(back[i], b);
  // Consecutive markers: count 1, then 1 << 8: 257 repeats, then one more pixel.
  const Bytes big = {10, 20, 130, 129, 1, 1, 1, 1, 1, 1, 1, 1, 9, 9, 200, 120};
  std::vector<Rgbe> line(259);
  ASSERT_EQ(decode(big, line), ScanStatus::ok);
  EXPECT_EQ(line[257], (Rgbe{10, 20, 130, 129}));
  EXPECT_EQ(line[258], (Rgbe{9, 9, 200, 120}));
  // A count running past the end of the line stops there.
  std::vector<Rgbe> shorter(100);
  ASSERT_EQ(decode(big, shorter), ScanStatus::ok);
  EXPECT_EQ(shorter[99], (Rgbe{10, 20, 130, 129}));
}

TEST(Scanline, DetectsCorruptAndTruncatedData) {
  std::vector<Rgbe> px(8);
  // Length in the header differs from the picture's.
  EXPECT_EQ(decode({2, 2, 0, 9, 137, 1, 137, 1, 137, 1, 137, 1}, px), ScanStatus::corrupt);
  // A run past the end of a plane.
  EXPECT_EQ(decode({2, 2, 0, 8, 137, 1}, px), ScanStatus::corrupt);
  // Literals past the end of a plane.
  EXPECT_EQ(decode({2, 2, 0, 8, 4, 1, 2, 3, 4, 5, 1, 2, 3, 4, 5}, px), ScanStatus::corrupt);
  // A repeat marker with nothing before it.
  EXPECT_EQ(decode({1, 1, 1, 4, 0, 0, 0, 0}, px), ScanStatus::corrupt);
  // Ends inside a plane, inside the header, inside a flat pixel, before anything.
  EXPECT_EQ(decode({2, 2, 0, 8, 136, 1, 136}, px), ScanStatus::truncated);
  EXPECT_EQ(decode({2, 2, 0}, px), ScanStatus::truncated);
  EXPECT_EQ(decode({5, 5, 5, 130, 6, 6}, px), ScanStatus::truncated);
  EXPECT_EQ(decode({}, px), ScanStatus::truncated);
}
