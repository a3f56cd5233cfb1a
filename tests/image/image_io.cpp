// Images by extension: OpenEXR, TIFF, PNG and Radiance pictures, checked through OpenImageIO.
#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <cmath>
#include <filesystem>

#include "radcl/image/image_io.h"
#include "radcl/image/picture.h"
#include "radcl/util/error.h"
#include "temp_dir.h"

using namespace radcl::image;

namespace {

std::string temp_path(const std::string& name) {
  static const radcl::test::TempFolder dir("image_io"); // removed at exit
  return (dir / name).string();
}

// A small gradient spanning dark, mid and over-range values, with depth.
FloatImage test_image(bool with_depth) {
  FloatImage img;
  img.width = 13;
  img.height = 7;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float t = (x + img.width * y) / 90.0f;
      img.rgb.push_back({t * t * 1.3f, t, 0.001f + 0.37f * (1 - t)});
      if (with_depth) img.depth.push_back(1.0f + x * 0.1f + y * 100.0f);
    }
  return img;
}

struct OiioPixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> f;
  std::vector<std::uint8_t> u8;
};

OiioPixels read_with_oiio(const std::string& path, bool as_u8) {
  OiioPixels out;
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return out;
  out.width = in->spec().width;
  out.height = in->spec().height;
  out.channels = in->spec().nchannels;
  const std::size_t n = std::size_t(out.width) * out.height * out.channels;
  if (as_u8) {
    out.u8.resize(n);
    EXPECT_TRUE(in->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::UINT8, out.u8.data()));
  } else {
    out.f.resize(n);
    EXPECT_TRUE(in->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::FLOAT, out.f.data()));
  }
  return out;
}

} // namespace

TEST(ImageIo, KindByExtension) {
  EXPECT_EQ(image_kind("a/b.HDR"), ImageKind::radiance);
  EXPECT_EQ(image_kind("x.pic"), ImageKind::radiance);
  EXPECT_EQ(image_kind("x.exr"), ImageKind::exr);
  EXPECT_EQ(image_kind("x.Tif"), ImageKind::tiff);
  EXPECT_EQ(image_kind("x.tiff"), ImageKind::tiff);
  EXPECT_EQ(image_kind("x.png"), ImageKind::png);
  EXPECT_FALSE(image_kind("x.jpg"));
  EXPECT_FALSE(image_kind("dir.exr/x"));
  EXPECT_THROW(write_image(temp_path("x.jpg"), test_image(false)), radcl::FatalError);
}

TEST(ImageIo, ToneMapIsExposureThenSrgb) {
  // Values from the formula in image_io.h, computed independently.
  EXPECT_EQ(tone_map_8bit(0.0f), 0);
  EXPECT_EQ(tone_map_8bit(-5.0f), 0);
  EXPECT_EQ(tone_map_8bit(0.001f), 3);
  EXPECT_EQ(tone_map_8bit(0.01f), 25);
  EXPECT_EQ(tone_map_8bit(0.2f), 124);
  EXPECT_EQ(tone_map_8bit(0.5f), 188);
  EXPECT_EQ(tone_map_8bit(0.75f), 225);
  EXPECT_EQ(tone_map_8bit(1.0f), 255);
  EXPECT_EQ(tone_map_8bit(2.0f), 255);
  EXPECT_EQ(tone_map_8bit(0.1f, 2.0), 124);
  EXPECT_EQ(tone_map_8bit(std::nanf("")), 0);
}

TEST(ImageIo, ExrFloatIsExactWithDepth) {
  const FloatImage img = test_image(true);
  const std::string path = temp_path("float.exr");
  ImageWriteOptions opt;
  opt.exr_pixel = ExrPixel::float32;
  write_image(path, img, opt);
  const OiioPixels o = read_with_oiio(path, false);
  ASSERT_EQ(o.width, img.width);
  ASSERT_EQ(o.height, img.height);
  ASSERT_EQ(o.channels, 4); // R G B Z
  for (std::size_t i = 0; i < img.rgb.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(o.f[4 * i + c], img.rgb[i][c]);
    ASSERT_EQ(o.f[4 * i + 3], img.depth[i]);
  }
  const FloatImage back = read_image(path);
  EXPECT_EQ(back.rgb, img.rgb);
  EXPECT_EQ(back.depth, img.depth);
}

TEST(ImageIo, ExrHalfWithinHalfPrecision) {
  const FloatImage img = test_image(false);
  const std::string path = temp_path("half.exr");
  write_image(path, img); // half is the default
  const OiioPixels o = read_with_oiio(path, false);
  ASSERT_EQ(o.width, img.width);
  ASSERT_EQ(o.height, img.height);
  ASSERT_EQ(o.channels, 3);
  for (std::size_t i = 0; i < img.rgb.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = img.rgb[i][c];
      ASSERT_EQ(o.f[3 * i + c], float(Imath::half(v))); // exactly the nearest half
      ASSERT_NEAR(o.f[3 * i + c], v, std::abs(v) * 0x1p-11f + 0x1p-24f);
    }
  const FloatImage back = read_image(path);
  EXPECT_TRUE(back.depth.empty());
  EXPECT_EQ(back.rgb[5][1], float(Imath::half(img.rgb[5][1])));
}

TEST(ImageIo, PngAndTiffAreToneMapped8Bit) {
  const FloatImage img = test_image(false);
  for (const char* name : {"tm.png", "tm.tif", "tm.tiff"}) {
    const std::string path = temp_path(name);
    ImageWriteOptions opt;
    opt.exposure = 1.7;
    write_image(path, img, opt);
    const OiioPixels o = read_with_oiio(path, true);
    ASSERT_EQ(o.width, img.width) << name;
    ASSERT_EQ(o.height, img.height);
    ASSERT_EQ(o.channels, 3);
    for (std::size_t i = 0; i < img.rgb.size(); ++i)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(o.u8[3 * i + c], tone_map_8bit(img.rgb[i][c], 1.7)) << name << " " << i;
    const FloatImage back = read_image(path);
    EXPECT_FLOAT_EQ(back.rgb[20][1], tone_map_8bit(img.rgb[20][1], 1.7) / 255.0f);
  }
}

TEST(ImageIo, FloatTiffIsExact) {
  const FloatImage img = test_image(false);
  const std::string path = temp_path("float.tif");
  ImageWriteOptions opt;
  opt.float_tiff = true;
  write_image(path, img, opt);
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(read_image(path).rgb, img.rgb);
}

TEST(ImageIo, RadiancePictureByExtension) {
  const FloatImage img = test_image(false);
  const std::string path = temp_path("io.hdr");
  write_image(path, img);
  const Picture pic = read_picture(path);
  EXPECT_EQ(pic.header.lines, (std::vector<std::string>{"#?RADIANCE", "FORMAT=32-bit_rle_rgbe"}));
  const FloatImage back = read_image(path);
  ASSERT_EQ(back.rgb.size(), img.rgb.size());
  for (std::size_t i = 0; i < img.rgb.size(); ++i)
    ASSERT_EQ(back.rgb[i], to_color(to_rgbe(img.rgb[i])));
  // OpenImageIO reads what we wrote.
  const OiioPixels o = read_with_oiio(path, false);
  EXPECT_EQ(o.width, img.width);
  EXPECT_EQ(o.height, img.height);

  ImageWriteOptions opt;
  opt.header.add_id().add_view(" -vtv -vh 30").add_exposure(2);
  write_image(path, img, opt);
  EXPECT_EQ(read_picture(path).header.lines,
            (std::vector<std::string>{"#?RADIANCE", "VIEW= -vtv -vh 30", "EXPOSURE=2.000000e+00",
                                      "FORMAT=32-bit_rle_rgbe"}));
}
