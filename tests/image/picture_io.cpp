// Whole pictures: header lines, orientations, streaming writes, damaged files, recovery.
#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <random>
#include <sstream>

#include "files.h"
#include "radcl/image/picture.h"
#include "radcl/image/scanline.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"

using namespace radcl::image;
using radcl::FatalError;

namespace {

std::vector<Rgbe> random_pixels(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Rgbe> px(n);
  for (auto& p : px) {
    // Mostly smooth with some runs, as rendered pictures are.
    if (rng() % 3 == 0 && &p != px.data()) {
      p = (&p)[-1];
      continue;
    }
    p = to_rgbe(std::ldexp(rng() % 1000 + 1, -8), std::ldexp(rng() % 1000, -8),
                std::ldexp(rng() % 1000, -8));
  }
  return px;
}

std::string temp_path(const std::string& name) {
  static const radcl::test::TempFolder dir("image_tests");
  return (dir / name).string();
}

std::string minimal_header() {
  return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
}

// Expects `f` to throw FatalError whose message contains `what`.
template <typename F> void expect_fatal(F f, const std::string& what) {
  try {
    f();
    ADD_FAILURE() << "no FatalError (expected one mentioning \"" << what << "\")";
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

Picture read_string(const std::string& bytes) {
  std::istringstream in(bytes);
  return read_picture(in, "test.hdr");
}

} // namespace

TEST(PictureHeader, LinesInRadianceForm) {
  PictureHeader h;
  h.add_id()
      .add_command({"rpict", "-vf", "my view.vf", "-x", "64"})
      .add_software("RADCL 0.1.0")
      .add_frame(3)
      .add_view(" -vtv -vp 0 0 0")
      .add_exposure(0.5)
      .add_pixaspect(1.5)
      .add_primaries()
      .add_format(PixelFormat::xyze);
  const std::vector<std::string> expect = {
      "#?RADIANCE",
      "rpict -vf \"my view.vf\" -x 64",
      "SOFTWARE= RADCL 0.1.0",
      "FRAME=3",
      "VIEW= -vtv -vp 0 0 0",
      "EXPOSURE=5.000000e-01",
      "PIXASPECT=1.500000",
      "PRIMARIES= 0.6400 0.3300 0.2900 0.6000 0.1500 0.0600 0.3333 0.3333",
      "FORMAT=32-bit_rle_xyze"};
  EXPECT_EQ(h.lines, expect);
  EXPECT_EQ(h.pixel_format(), PixelFormat::xyze);
  EXPECT_EQ(h.frame(), 3);
  EXPECT_EQ(h.software(), "RADCL 0.1.0");
  EXPECT_EQ(h.commands(), std::vector<std::string>{"rpict -vf \"my view.vf\" -x 64"});

  std::ostringstream out;
  write_header(out, h);
  std::string text;
  for (const auto& l : expect)
    text += l + "\n";
  EXPECT_EQ(out.str(), text + "\n");
}

TEST(PictureHeader, DatesAreCapdateThenGmt) {
  PictureHeader h;
  h.add_dates(0);
  ASSERT_EQ(h.lines.size(), 2u);
  EXPECT_EQ(h.lines[0].rfind("CAPDATE= ", 0), 0u);
  EXPECT_EQ(h.lines[1], "GMT= 1970:01:01 00:00:00");
}

TEST(PictureHeader, ReadsRadianceVariants) {
  const std::string text = "#?RADIANCE\nEXPOSURE=2\nEXPOSURE= 1.5\nPIXASPECT=0.5\n"
                           "COLORCORR= 1 2 3\nCOLORCORR= 2 2 2\nFORMAT= 32-bit_rle_rgbe  \n"
                           "VIEW= -vtv -vh 40\nVIEW= -vv 30\n" +
                           std::string(3000, 'a') + "\n\r\nrest";
  std::istringstream in(text);
  const PictureHeader h = read_header(in, "x");
  EXPECT_DOUBLE_EQ(h.exposure(), 3.0);
  EXPECT_DOUBLE_EQ(h.pixaspect(), 0.5);
  EXPECT_EQ(h.colorcorr(), (std::array<double, 3>{2, 4, 6}));
  EXPECT_EQ(h.format(), "32-bit_rle_rgbe");
  EXPECT_EQ(h.views(), (std::vector<std::string>{" -vtv -vh 40", " -vv 30"}));
  // The long line is split at Radiance's line limit; "\r\n" ends the header.
  ASSERT_EQ(h.lines.size(), 11u);
  EXPECT_EQ(h.lines[9].size(), 2046u);
  EXPECT_EQ(h.lines[10].size(), 3000u - 2046u);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "rest");

  // A later frame of an rpict -S stream has no id line; readers accept it.
  std::istringstream frame("FRAME=2\nVIEW= -vtv\nFORMAT=32-bit_rle_rgbe\n\n");
  const PictureHeader f = read_header(frame, "x");
  EXPECT_EQ(f.id(), "");
  EXPECT_EQ(f.frame(), 2);
}

TEST(Resolution, AllEightOrientations) {
  const char* lines[] = {"-Y 3 +X 2", "-Y 3 -X 2", "+Y 3 +X 2", "+Y 3 -X 2",
                         "+X 2 +Y 3", "+X 2 -Y 3", "-X 2 +Y 3", "-X 2 -Y 3"};
  for (const char* l : lines) {
    const auto r = Resolution::parse(l);
    ASSERT_TRUE(r) << l;
    EXPECT_EQ(r->xres, 2);
    EXPECT_EQ(r->yres, 3);
    EXPECT_EQ(r->to_string(), std::string(l) + "\n");
  }
  EXPECT_FALSE(Resolution::parse("-Y 0 +X 5"));
  EXPECT_FALSE(Resolution::parse("-Y 5"));
  EXPECT_FALSE(Resolution::parse("garbage"));
  EXPECT_TRUE(Resolution::parse("-Y 3 +X 2")->is_standard());
}

TEST(Picture, WriteThenReadIsBitExact) {
  const int w = 37, h = 23;
  const auto px = random_pixels(w * h, 1);
  PictureHeader hdr;
  hdr.add_id().add_command({"rpict", "-x", "37"}).add_view(" -vtv").add_format();
  const std::string path = temp_path("roundtrip.hdr");
  write_picture(path, hdr, w, h, px);
  const Picture pic = read_picture(path);
  EXPECT_EQ(pic.width, w);
  EXPECT_EQ(pic.height, h);
  EXPECT_EQ(pic.header.lines, hdr.lines);
  EXPECT_EQ(pic.pixels, px);
}

TEST(Picture, StreamingMatchesWholeAndColorsConvert) {
  const int w = 16, h = 5;
  std::vector<Color> colors(w * h);
  for (int i = 0; i < w * h; ++i)
    colors[i] = {0.01f * i, 0.5f, 100.0f / (i + 1)};
  PictureHeader hdr;
  hdr.add_id().add_format();
  std::ostringstream streamed;
  PictureWriter wr(streamed, hdr, Resolution::standard(w, h));
  for (int y = 0; y < h; ++y) {
    wr.write_scanline(std::span<const Color>(colors).subspan(y * w, w));
    wr.flush();
  }
  EXPECT_EQ(wr.scanlines_written(), h);
  std::vector<Rgbe> px(w * h);
  for (int i = 0; i < w * h; ++i)
    px[i] = to_rgbe(colors[i]);
  std::ostringstream whole;
  write_picture(whole, hdr, w, h, px);
  EXPECT_EQ(streamed.str(), whole.str());
  EXPECT_EQ(read_string(whole.str()).pixels, px);
}

// Each orientation: build the file by the definition in picture-format.md §3 (first axis named =
// scanlines, '-' = decreasing, y up), read it, compare with the top-down picture.
TEST(Picture, ReadsEveryOrientationTopDown) {
  const int w = 9, h = 4; // scanlines of 9 (RLE) or 4 (flat) pixels
  const auto top_down = random_pixels(w * h, 2);
  for (bool y_major : {true, false}) {
    for (bool xdec : {false, true}) {
      for (bool ydec : {false, true}) {
        Resolution r{w, h, y_major, xdec, ydec};
        std::string file = minimal_header() + r.to_string();
        std::vector<unsigned char> data;
        const int ns = y_major ? h : w, sl = y_major ? w : h;
        for (int s = 0; s < ns; ++s) {
          std::vector<Rgbe> line(sl);
          for (int p = 0; p < sl; ++p) {
            const int xi = y_major ? p : s, yi = y_major ? s : p;
            const int x = xdec ? w - 1 - xi : xi;
            const int y_up = ydec ? h - 1 - yi : yi;
            line[p] = top_down[(h - 1 - y_up) * w + x];
          }
          encode_scanline(line, data);
        }
        file.append(data.begin(), data.end());
        const Picture pic = read_string(file);
        EXPECT_EQ(pic.width, w);
        EXPECT_EQ(pic.height, h);
        EXPECT_EQ(pic.resolution, r);
        EXPECT_EQ(pic.pixels, top_down) << r.to_string();
      }
    }
  }
}

TEST(Picture, ReadsBottomUpAndFlatPictures) {
  // A 2x2 "+Y" picture by hand: the first scanline is the bottom row.
  const Rgbe a{200, 0, 0, 129}, b{0, 200, 0, 129}, c{0, 0, 200, 129}, d{200, 200, 200, 129};
  std::string file = minimal_header() + "+Y 2 +X 2\n";
  for (const Rgbe& p : {c, d, a, b})
    file.append(p.begin(), p.end());
  Picture pic = read_string(file);
  EXPECT_EQ(pic.pixels, (std::vector<Rgbe>{a, b, c, d}));

  // A picture with flat (non-RLE) scanlines of RLE-able length, as old writers made.
  const int w = 20, h = 3;
  const auto px = random_pixels(w * h, 4);
  file = minimal_header() + "-Y 3 +X 20\n";
  for (const Rgbe& p : px)
    file.append(p.begin(), p.end());
  pic = read_string(file);
  EXPECT_EQ(pic.pixels, px);
}

TEST(Picture, TruncatedOrCorruptFilesAreFatal) {
  const std::string good =
      radcl::test::read_file(radcl::test::data("results/materials_plain_view_ab0.hdr"));
  const auto header_end = good.find("\n\n") + 2;
  const auto data_start = good.find('\n', header_end) + 1;
  expect_fatal([&] { read_string(""); }, "not a Radiance file");
  expect_fatal([&] { read_string("\x02\x02\x01"); }, "not a Radiance file");
  expect_fatal([&] { read_string(good.substr(0, 40)); }, "end of header");
  expect_fatal([&] { read_string(good.substr(0, header_end)); }, "resolution");
  expect_fatal([&] { read_string(good.substr(0, data_start + 1000)); }, "truncated");
  expect_fatal([&] { read_string(good.substr(0, good.size() - 1)); }, "241 of 242 scanlines");
  expect_fatal([&] { read_string("#?RADIANCE\nFORMAT=ascii\n\n-Y 1 +X 1\n"); },
               "not a Radiance picture");
  expect_fatal([&] { read_string(minimal_header() + "-Y 100000 +X 100000\n"); }, "too large");
  std::string bad_len = good;
  bad_len[data_start + 3] ^= 1; // the first scanline's RLE length
  expect_fatal([&] { read_string(bad_len); }, "bad scanline encoding");
  expect_fatal([] { read_picture("/nonexistent/x.hdr"); }, "cannot open");

  // Random damage anywhere after the header: a clear error or a picture, never a crash.
  std::mt19937 rng(5);
  int errors = 0;
  for (int t = 0; t < 300; ++t) {
    std::string bytes = good;
    for (int k = 0; k < 1 + t % 8; ++k)
      bytes[data_start + rng() % (bytes.size() - data_start)] = static_cast<char>(rng());
    if (t % 3 == 0) bytes.resize(data_start + rng() % (bytes.size() - data_start));
    try {
      const Picture p = read_string(bytes);
      EXPECT_EQ(p.pixels.size(), 384u * 242u);
    } catch (const FatalError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 50);
}

// Found by fuzz_picture_reader: a few bytes claiming 2^30 pixels made the reader allocate
// (and clear) 4 GiB before finding the data truncated. Storage now follows the data.
TEST(Picture, HugeClaimWithLittleDataFailsAtOnce) {
  const std::string head = minimal_header() + "-Y 32768 +X 32768\n";
  expect_fatal([&] { read_string(head + std::string(4 * 100, '\x40')); }, "truncated");
  expect_fatal([&] { read_string(minimal_header() + "-Y 38888888888888888888 +X 2\n"); },
               "resolution");
}

TEST(Picture, RecoverCountsCompleteScanlines) {
  const std::string ref = radcl::test::data("results/cornell_view.hdr");
  const std::string good = radcl::test::read_file(ref);
  const Picture pic = read_picture(ref);
  const auto data_start = good.find('\n', good.find("\n\n") + 2) + 1;
  // Where each scanline ends in the file.
  std::vector<std::size_t> ends;
  std::size_t at = data_start;
  for (int y = 0; y < pic.height; ++y) {
    std::vector<unsigned char> enc;
    encode_scanline(std::span<const Rgbe>(pic.pixels).subspan(y * pic.width, pic.width), enc);
    at += enc.size();
    ends.push_back(at);
  }
  ASSERT_EQ(ends.back(), good.size());
  const std::string path = temp_path("recover.hdr");
  for (int k : {0, 1, 17, 100, 255}) {
    const std::size_t cut = k == 0 ? data_start + 3 : ends[k - 1] + (k % 2 ? 5 : 0);
    radcl::test::write_file(path, good.substr(0, cut));
    const Salvage s = salvage_picture(path);
    EXPECT_EQ(s.complete, k);
    EXPECT_EQ(s.resolution, pic.resolution);
    EXPECT_EQ(s.header.lines, pic.header.lines);
    ASSERT_EQ(s.pixels.size(), std::size_t(k) * pic.width);
    EXPECT_TRUE(std::equal(s.pixels.begin(), s.pixels.end(), pic.pixels.begin()));
  }
  radcl::test::write_file(path, good);
  EXPECT_EQ(salvage_picture(path).complete, pic.height);
  // Resuming: copy what was salvaged, then write the rest; the result is the original file.
  radcl::test::write_file(path, good.substr(0, ends[99] + 10));
  const Salvage s = salvage_picture(path);
  std::ostringstream out;
  PictureWriter w(out, s.header, s.resolution);
  for (int y = 0; y < pic.height; ++y) {
    const auto& src = y < s.complete ? s.pixels : pic.pixels;
    w.write_scanline(std::span<const Rgbe>(src).subspan(y * pic.width, pic.width));
  }
  EXPECT_TRUE(out.str() == good);

  radcl::test::write_file(path, "#?RADIANCE\n\n");
  expect_fatal([&] { salvage_picture(path); }, "bad recover file");
  expect_fatal([] { salvage_picture("/nonexistent/r.hdr"); }, "cannot open recover file");
}
