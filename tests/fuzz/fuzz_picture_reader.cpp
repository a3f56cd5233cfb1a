// The RGBE picture reader: the whole picture (reoriented), then the scanline-by-scanline
// salvage rpict -r does, and the header values readers parse.
#include <sstream>
#include <vector>

#include "fuzz_target.h"
#include "radcl/image/picture.h"

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
    std::vector<Rgbe> line(static_cast<std::size_t>(reader.resolution().scanline_length()));
    while (reader.try_read_scanline(line)) {
    }
  }
  std::istringstream in{std::string(data)};
  (void)read_picture(in, "fuzz.hdr").colors();
}
