// TIFF and PNG through OpenImageIO, in the module libradcl_oiio (src/image/plugin/), opened on
// first use: programs that never write such a file do not load OpenImageIO's libraries.
// Builds configured with RADCL_WITH_OIIO=OFF have no module and say so.
#include <cstdlib>
#include <dlfcn.h>
#include <mutex>
#include <string>
#include <vector>

#include "image_formats.h"
#include "radcl/image/oiio_plugin.h"
#include "radcl/util/error.h"
#include "radcl/util/library_path.h"
#include "radcl/util/program_folder.h"

namespace radcl::image::detail {
namespace {

struct Plugin {
  decltype(&radcl_oiio_write) write = nullptr;
  decltype(&radcl_oiio_read) read = nullptr;
  std::string error; // why it could not be opened
};

// The file RADCL_OIIO_PLUGIN names, else the installed library folder beside the program,
// then ../lib/ (the build tree).
Plugin open_plugin() {
  Plugin p;
#ifndef RADCL_WITH_OIIO
  p.error = "this build has no OpenImageIO (TIFF, PNG)";
#else
  std::vector<std::string> tries;
  if (const char* e = std::getenv("RADCL_OIIO_PLUGIN"); e && *e) {
    tries.emplace_back(e);
  } else {
    tries.push_back(installed_library_dir() + "/" RADCL_OIIO_PLUGIN_NAME);
    tries.push_back(program_folder() + "/../lib/" RADCL_OIIO_PLUGIN_NAME); // the build tree
  }
  for (const std::string& f : tries) {
    void* h = ::dlopen(f.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) {
      if (p.error.empty()) p.error = ::dlerror();
      continue;
    }
    p.write = reinterpret_cast<decltype(&radcl_oiio_write)>(::dlsym(h, "radcl_oiio_write"));
    p.read = reinterpret_cast<decltype(&radcl_oiio_read)>(::dlsym(h, "radcl_oiio_read"));
    if (p.write && p.read) return p;
    p.error = f + " lacks radcl_oiio_write/radcl_oiio_read";
    p.write = nullptr;
    p.read = nullptr;
  }
  p.error = "cannot load OpenImageIO support (" RADCL_OIIO_PLUGIN_NAME "): " + p.error;
#endif
  return p;
}

const Plugin& plugin() {
  static std::once_flag once;
  static Plugin p;
  std::call_once(once, [] { p = open_plugin(); });
  return p;
}

} // namespace

void write_oiio(const std::string& path, const FloatImage& img, bool as_float, double exposure) {
  const Plugin& p = plugin();
  if (!p.write) throw FatalError("cannot write \"" + path + "\": " + p.error);
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
  std::vector<float> f;
  std::vector<std::uint8_t> u8;
  if (as_float) {
    f.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        f[3 * i + c] = img.rgb[i][c];
  } else {
    u8.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        u8[3 * i + c] = tone_map_8bit(img.rgb[i][c], exposure);
  }
  char err[512] = "";
  const void* px = as_float ? static_cast<const void*>(f.data()) : u8.data();
  if (!p.write(path.c_str(), img.width, img.height, as_float ? 1 : 0, px, err, sizeof err))
    throw FatalError("cannot write \"" + path + "\": " + err);
}

FloatImage read_oiio(const std::string& path) {
  const Plugin& p = plugin();
  if (!p.read) throw FatalError("cannot read \"" + path + "\": " + p.error);
  char err[512] = "";
  int w = 0, h = 0;
  float* rgb = nullptr;
  if (!p.read(path.c_str(), &w, &h, &rgb, err, sizeof err))
    throw FatalError("cannot read \"" + path + "\": " + err);
  FloatImage img;
  img.width = w;
  img.height = h;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  img.rgb.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      img.rgb[i][c] = rgb[3 * i + c];
  std::free(rgb);
  return img;
}

} // namespace radcl::image::detail
