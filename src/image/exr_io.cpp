// OpenEXR through its C++ API: scanline files, ZIP compression (the library's default).
#include <Imath/ImathBox.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <exception>

#include "image_formats.h"
#include "radcl/util/error.h"

namespace radcl::image::detail {

void write_exr(const std::string& path, const FloatImage& img, ExrPixel pixel) {
  const int w = img.width;
  const int h = img.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const bool half = pixel == ExrPixel::half;
  std::vector<Imath::half> hbuf;
  if (half) {
    hbuf.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        hbuf[3 * i + c] = Imath::half(img.rgb[i][c]);
  }
  try {
    Imf::Header header(w, h);
    const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
    for (const char* ch : {"R", "G", "B"})
      header.channels().insert(ch, Imf::Channel(type));
    if (!img.depth.empty()) header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      char* base = half ? reinterpret_cast<char*>(hbuf.data() + c)
                        : const_cast<char*>(reinterpret_cast<const char*>(&img.rgb[0][c]));
      const std::size_t px = half ? 3 * sizeof(Imath::half) : sizeof(Color);
      fb.insert(names[c], Imf::Slice(type, base, px, px * w));
    }
    if (!img.depth.empty())
      fb.insert("Z", Imf::Slice(Imf::FLOAT,
                                const_cast<char*>(reinterpret_cast<const char*>(img.depth.data())),
                                sizeof(float), sizeof(float) * w));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(h);
  } catch (const std::exception& e) {
    throw FatalError("cannot write OpenEXR file \"" + path + "\": " + e.what());
  }
}

FloatImage read_exr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    FloatImage img;
    img.width = dw.max.x - dw.min.x + 1;
    img.height = dw.max.y - dw.min.y + 1;
    const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
    img.rgb.assign(n, Color{0, 0, 0});
    const bool has_z = file.header().channels().findChannel("Z") != nullptr;
    if (has_z) img.depth.assign(n, 0.0f);
    // Slices address pixel (x, y) at base + x*xs + y*ys, so offset the base by the window origin.
    const std::ptrdiff_t origin = static_cast<std::ptrdiff_t>(dw.min.y) * img.width + dw.min.x;
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
      fb.insert(names[c],
                Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&img.rgb[0][c] - 3 * origin),
                           sizeof(Color), sizeof(Color) * img.width));
    if (has_z)
      fb.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(img.depth.data() - origin),
                                sizeof(float), sizeof(float) * img.width));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return img;
  } catch (const std::exception& e) {
    throw FatalError("cannot read OpenEXR file \"" + path + "\": " + e.what());
  }
}

} // namespace radcl::image::detail
