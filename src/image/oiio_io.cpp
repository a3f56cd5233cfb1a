// TIFF and PNG through OpenImageIO (left out of builds configured with RADCL_WITH_OIIO=OFF).
#include "image_formats.h"
#include "radcl/util/error.h"

#ifndef RADCL_WITH_OIIO
namespace radcl::image::detail {

void write_oiio(const std::string& path, const FloatImage&, bool, double) {
  throw FatalError("cannot write \"" + path + "\": this build has no OpenImageIO (TIFF, PNG)");
}

FloatImage read_oiio(const std::string& path) {
  throw FatalError("cannot read \"" + path + "\": this build has no OpenImageIO (TIFF, PNG)");
}

} // namespace radcl::image::detail
#else
#include <OpenImageIO/imageio.h>

namespace radcl::image::detail {

void write_oiio(const std::string& path, const FloatImage& img, bool as_float, double exposure) {
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw FatalError("cannot write \"" + path + "\": " + OIIO::geterror());
  const OIIO::TypeDesc type = as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(img.width, img.height, 3, type);
  spec.attribute("oiio:ColorSpace", as_float ? "linear" : "sRGB");
  bool ok = out->open(path, spec);
  if (ok && as_float) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, img.rgb.data());
  } else if (ok) {
    std::vector<std::uint8_t> px(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        px[3 * i + c] = tone_map_8bit(img.rgb[i][c], exposure);
    ok = out->write_image(OIIO::TypeDesc::UINT8, px.data());
  }
  ok = out->close() && ok;
  if (!ok) throw FatalError("cannot write \"" + path + "\": " + out->geterror());
}

FloatImage read_oiio(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw FatalError("cannot read \"" + path + "\": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int nch = spec.nchannels;
  FloatImage img;
  img.width = spec.width;
  img.height = spec.height;
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
  std::vector<float> px(n * nch);
  if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, px.data()))
    throw FatalError("cannot read \"" + path + "\": " + in->geterror());
  img.rgb.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      img.rgb[i][c] = px[i * nch + (nch >= 3 ? c : 0)];
  return img;
}

} // namespace radcl::image::detail
#endif
