// libradcl_oiio: TIFF and PNG through OpenImageIO, loaded by radcl_image only when such a file
// is written or read (src/image/oiio_io.cpp). OpenImageIO pulls in some 250 shared libraries
// whose loading and start-up cost every rpict run about 0.3 s, twice where the program re-runs
// itself for huge pages; a plain C interface keeps this module free of radcl's own libraries.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include <OpenImageIO/imageio.h>

#include "radcl/image/oiio_plugin.h"

namespace {

int fail(char* err, std::size_t n, const std::string& what) {
  if (n) {
    std::strncpy(err, what.c_str(), n - 1);
    err[n - 1] = '\0';
  }
  return 0;
}

} // namespace

extern "C" int radcl_oiio_write(const char* path, int width, int height, int as_float,
                                const void* pixels, char* err, std::size_t errlen) {
  try {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return fail(err, errlen, OIIO::geterror());
    const OIIO::TypeDesc type = as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(width, height, 3, type);
    spec.attribute("oiio:ColorSpace", as_float ? "linear" : "sRGB");
    bool ok = out->open(path, spec) && out->write_image(type, pixels);
    ok = out->close() && ok;
    return ok ? 1 : fail(err, errlen, out->geterror());
  } catch (const std::exception& e) {
    return fail(err, errlen, e.what());
  }
}

extern "C" int radcl_oiio_read(const char* path, int* width, int* height, float** rgb, char* err,
                               std::size_t errlen) {
  try {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return fail(err, errlen, OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int nch = spec.nchannels;
    const std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
    std::string px(n * nch * sizeof(float), '\0');
    if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, px.data()))
      return fail(err, errlen, in->geterror());
    const auto* f = reinterpret_cast<const float*>(px.data());
    auto* out = static_cast<float*>(std::malloc(std::max<std::size_t>(1, 3 * n * sizeof(float))));
    if (!out) return fail(err, errlen, "out of memory");
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        out[3 * i + c] = f[i * nch + (nch >= 3 ? c : 0)];
    *width = spec.width;
    *height = spec.height;
    *rgb = out;
    return 1;
  } catch (const std::exception& e) {
    return fail(err, errlen, e.what());
  }
}
