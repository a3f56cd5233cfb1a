// The reference pictures rpict 5.4a wrote (tests/data/results/*.hdr): read them, check header,
// size and pixels, and re-encode their pixels to the same bytes rpict wrote.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <array>
#include <iterator>
#include <span>
#include <sstream>

#include "files.h"
#include "radcl/image/picture.h"
#include "radcl/image/scanline.h"
#include "test_env.h"

using namespace radcl::image;

namespace {

struct Spot {
  int x, row; // row counted from the top
  Rgbe rgbe;
};

struct Reference {
  const char* file;
  int width, height;
  const char* command;           // rpict's line in the header
  const char* view;              // VIEW= value
  std::array<long, 4> byte_sums; // sum of each of R, G, B, E over all pixels
  std::array<Spot, 4> spots;
};

// Sizes, sums and spot values come from an independent decoder (a short Python script written
// from picture-format.md) run on the same files.
const Reference kRefs[] = {
    {"cornell_ab0_view.hdr",
     256,
     256,
     "rpict -vf cornell.vf -x 256 -y 256 -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ps 1",
     " -vtv -vp 0.5 0.02 0.5 -vd 0 1 0 -vu 0 0 1 -vh 70 -vv 70 -vo 0 -va 0 -vs 0 -vl 0",
     {9615458, 8163863, 4814614, 7221645},
     {{{0, 0, {0, 0, 0, 0}},
       {128, 128, {140, 126, 93, 127}},
       {255, 255, {137, 123, 91, 126}},
       {85, 51, {136, 122, 90, 126}}}}},
    {"materials_plain_view_ab0.hdr",
     384,
     242,
     "rpict -vf materials.vf -x 384 -y 256 -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ps 1",
     " -vtv -vp 0 -7 2.2 -vd 0 1 -0.25 -vu 0 0 1 -vh 60 -vv 40 -vo 0 -va 0 -vs 0 -vl 0",
     {9281144, 9106234, 10168978, 9598305},
     {{{0, 0, {115, 115, 147, 129}},
       {192, 121, {21, 42, 128, 134}},
       {383, 241, {131, 131, 131, 134}},
       {128, 48, {0, 0, 0, 0}}}}},
    {"office_view.hdr",
     256,
     193,
     "rpict -vf office.vf -x 256 -y 256 -ab 2 -ad 1024 -as 256 -aa 0.15 -ar 128",
     " -vtv -vp 3 3.7 1.5 -vd 0 -1 -0.12 -vu 0 0 1 -vh 75 -vv 60 -vo 0 -va 0 -vs 0 -vl 0",
     {9304865, 8641818, 8293872, 6404811},
     {{{0, 0, {193, 179, 167, 128}},
       {128, 96, {127, 127, 128, 133}},
       {255, 192, {132, 118, 111, 128}},
       {85, 38, {189, 189, 210, 133}}}}},
    {"cornell_view.hdr",
     256,
     256,
     "rpict -vf cornell.vf -x 256 -y 256 -ab 3 -ad 512 -as 128 -aa 0.15 -ar 64 -ps 2 -pt 0.05",
     " -vtv -vp 0.5 0.02 0.5 -vd 0 1 0 -vu 0 0 1 -vh 70 -vv 70 -vo 0 -va 0 -vs 0 -vl 0",
     {11293933, 9130441, 4596009, 8287556},
     {{{0, 0, {136, 84, 52, 126}},
       {128, 128, {243, 200, 134, 127}},
       {255, 255, {219, 221, 131, 126}},
       {85, 51, {164, 122, 80, 127}}}}},
    {"luminaires_view.hdr",
     320,
     199,
     "rpict -vf luminaires.vf -x 320 -y 220 -ab 2 -ad 512 -as 128 -aa 0.15 -ar 64",
     " -vtv -vp 0.5 0.5 1.6 -vd 1 0.8 -0.15 -vu 0 0 1 -vh 80 -vv 55 -vo 0 -va 0 -vs 0 -vl 0",
     {11681603, 10923496, 10277118, 8160038},
     {{{0, 0, {179, 165, 145, 129}},
       {160, 99, {136, 134, 128, 128}},
       {319, 198, {172, 148, 130, 127}},
       {106, 39, {185, 188, 195, 129}}}}},
};

class ReferencePicture : public ::testing::TestWithParam<Reference> {
protected:
  std::string path() const { return radcl::test::data(std::string("results/") + GetParam().file); }
};

} // namespace

TEST_P(ReferencePicture, SizeHeaderAndPixels) {
  const Reference& ref = GetParam();
  const Picture pic = read_picture(path());
  EXPECT_EQ(pic.width, ref.width);
  EXPECT_EQ(pic.height, ref.height);
  EXPECT_TRUE(pic.resolution.is_standard());
  EXPECT_EQ(pic.resolution.to_string(),
            "-Y " + std::to_string(ref.height) + " +X " + std::to_string(ref.width) + "\n");

  const PictureHeader& h = pic.header;
  ASSERT_EQ(h.lines.size(), 9u);
  EXPECT_EQ(h.lines[0], "#?RADIANCE");
  EXPECT_EQ(h.id(), "RADIANCE");
  EXPECT_EQ(h.format(), "32-bit_rle_rgbe");
  EXPECT_EQ(h.pixel_format(), PixelFormat::rgbe);
  ASSERT_EQ(h.views().size(), 1u);
  EXPECT_EQ(h.views()[0], ref.view);
  const auto cmds = h.commands();
  ASSERT_EQ(cmds.size(), 2u); // oconv's line from the octree, then rpict's
  EXPECT_EQ(cmds[0].rfind("oconv ", 0), 0u);
  EXPECT_EQ(cmds[1], ref.command);
  EXPECT_EQ(h.software(), "RADIANCE 5.4a 2026-11-22 LBNL (5.2.Unknown)");
  EXPECT_DOUBLE_EQ(h.exposure(), 1.0);
  EXPECT_DOUBLE_EQ(h.pixaspect(), 1.0);
  const auto prim = h.primaries();
  ASSERT_TRUE(prim.has_value());
  EXPECT_FLOAT_EQ((*prim)[0], 0.64f);
  EXPECT_FLOAT_EQ((*prim)[7], 0.3333f);
  EXPECT_TRUE(h.value("CAPDATE").has_value());
  EXPECT_TRUE(h.value("GMT").has_value());

  std::array<long, 4> sums{};
  for (const Rgbe& p : pic.pixels)
    for (int c = 0; c < 4; ++c)
      sums[c] += p[c];
  EXPECT_EQ(sums, ref.byte_sums);
  for (const Spot& s : ref.spots)
    EXPECT_EQ(pic.at(s.x, s.row), s.rgbe) << s.x << "," << s.row;
}

// OpenImageIO's own RGBE decoder (it omits Radiance's +0.5) must agree within one code step.
TEST_P(ReferencePicture, AgreesWithOpenImageIO) {
  const Picture pic = read_picture(path());
  const auto colors = pic.colors();
  auto in = OIIO::ImageInput::open(path());
  ASSERT_TRUE(in) << OIIO::geterror();
  ASSERT_EQ(in->spec().width, pic.width);
  ASSERT_EQ(in->spec().height, pic.height);
  std::vector<float> px(colors.size() * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
  for (std::size_t i = 0; i < colors.size(); ++i) {
    const float step = pic.pixels[i][3] ? std::ldexp(1.0f, pic.pixels[i][3] - 136) : 0.0f;
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(px[3 * i + c], colors[i][c], step) << "pixel " << i << " channel " << c;
  }
}

TEST_P(ReferencePicture, ReencodesByteForByte) {
  const std::string bytes = radcl::test::read_file(path());
  std::istringstream in(bytes);
  PictureReader reader(in, path());
  const auto data_start = static_cast<std::size_t>(in.tellg());
  const Resolution& r = reader.resolution();
  std::vector<Rgbe> line(r.scanline_length());
  std::vector<unsigned char> encoded;
  for (int s = 0; s < r.num_scanlines(); ++s) {
    reader.read_scanline(line);
    encode_scanline(line, encoded);
  }
  EXPECT_EQ(in.peek(), EOF) << "data after the last scanline";
  ASSERT_EQ(encoded.size(), bytes.size() - data_start);
  EXPECT_TRUE(std::equal(encoded.begin(), encoded.end(),
                         reinterpret_cast<const unsigned char*>(bytes.data() + data_start)));

  // The whole file, header included, comes back when written with the header read.
  std::ostringstream out;
  const Picture pic = read_picture(path());
  write_picture(out, pic.header, pic.width, pic.height, pic.pixels);
  EXPECT_TRUE(out.str() == bytes);
}

INSTANTIATE_TEST_SUITE_P(Rpict54a, ReferencePicture, ::testing::ValuesIn(kRefs),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           n = n.substr(0, n.find('.'));
                           return n;
                         });
