#include "radcl/image/image_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "image_formats.h"
#include "radcl/image/picture.h"
#include "radcl/util/error.h"

namespace radcl::image {
namespace {

void write_radiance(const std::string& path, const FloatImage& img, const ImageWriteOptions& o) {
  PictureHeader h = o.header;
  if (h.lines.empty()) h.add_id();
  if (h.format().empty()) h.add_format();
  std::vector<Rgbe> px(img.rgb.size());
  std::transform(img.rgb.begin(), img.rgb.end(), px.begin(),
                 [](const Color& c) { return to_rgbe(c); });
  write_picture(path, h, img.width, img.height, px);
}

FloatImage read_radiance(const std::string& path) {
  const Picture pic = read_picture(path);
  return {pic.width, pic.height, pic.colors(), {}};
}

} // namespace

std::optional<ImageKind> image_kind(const std::string& path) {
  const auto dot = path.rfind('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "hdr" || ext == "pic") return ImageKind::radiance;
  if (ext == "exr") return ImageKind::exr;
  if (ext == "tif" || ext == "tiff") return ImageKind::tiff;
  if (ext == "png") return ImageKind::png;
  return std::nullopt;
}

std::uint8_t tone_map_8bit(float v, double exposure) {
  double x = exposure * v;
  if (!(x > 0.0)) x = 0.0; // NaN too
  if (x > 1.0) x = 1.0;
  const double s = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(s, 0.0, 1.0)));
}

void write_image(const std::string& path, const FloatImage& img, const ImageWriteOptions& opt) {
  const auto n = static_cast<std::size_t>(img.width) * img.height;
  if (img.width <= 0 || img.height <= 0 || img.rgb.size() != n ||
      (!img.depth.empty() && img.depth.size() != n))
    throw FatalError("internal error: inconsistent image for \"" + path + "\"");
  const auto kind = image_kind(path);
  if (!kind) throw FatalError("unknown image type for \"" + path + "\"");
  switch (*kind) {
  case ImageKind::radiance:
    return write_radiance(path, img, opt);
  case ImageKind::exr:
    return detail::write_exr(path, img, opt.exr_pixel);
  case ImageKind::tiff:
    return detail::write_oiio(path, img, opt.float_tiff, opt.exposure);
  case ImageKind::png:
    return detail::write_oiio(path, img, false, opt.exposure);
  }
}

FloatImage read_image(const std::string& path) {
  const auto kind = image_kind(path);
  if (!kind) throw FatalError("unknown image type for \"" + path + "\"");
  switch (*kind) {
  case ImageKind::radiance:
    return read_radiance(path);
  case ImageKind::exr:
    return detail::read_exr(path);
  case ImageKind::tiff:
  case ImageKind::png:
    break;
  }
  return detail::read_oiio(path);
}

} // namespace radcl::image
