// Writers and readers behind image_io.h's dispatch, one per library.
#pragma once

#include <string>

#include "radcl/image/image_io.h"

namespace radcl::image::detail {

void write_exr(const std::string& path, const FloatImage& img, ExrPixel pixel);
FloatImage read_exr(const std::string& path);

// TIFF/PNG through OpenImageIO: 8-bit tone-mapped, or float RGB when `as_float`.
void write_oiio(const std::string& path, const FloatImage& img, bool as_float, double exposure);
FloatImage read_oiio(const std::string& path);

} // namespace radcl::image::detail
