// The RGBE picture reader: the header values readers parse, the scanline-by-scanline salvage
// rpict -r does, then the whole picture (reoriented). Run-length codes let a few bytes stand
// for a huge valid picture, so pictures declared larger than the limits below are only read
// up to their resolution string: memory for them would say nothing about the reader.
#include <sstream>
#include <vector>

#include "fuzz_target.h"
#include "radcl/image/picture.h"

namespace {
constexpr long long kMaxPixels = 1LL << 24;   // 64 MiB of pixels
constexpr long long kMaxScanline = 1LL << 20; // pixels in one scanline
} // namespace

RADCL_FUZZ_TARGET(picture_reader) {
  using namespace radcl::image;
  {
    std::istringstream in{std::string(data)};
    PictureReader reader(in, "fuzz.hdr");
    const PictureHeader& h = reader.header();
    (void)h.exposure();
    (void)h.pixaspect();
    (void)h.colorcorr();
    (void)h.primaries();
    (void)h.views();
    (void)h.software();
    (void)h.frame();
    (void)h.commands();
    const Resolution& r = reader.resolution();
    if (static_cast<long long>(r.xres) * r.yres > kMaxPixels || r.scanline_length() > kMaxScanline)
      return;
    std::vector<Rgbe> line(static_cast<std::size_t>(r.scanline_length()));
    while (reader.try_read_scanline(line)) {
    }
  }
  std::istringstream in{std::string(data)};
  (void)read_picture(in, "fuzz.hdr").colors();
}
