// Writing and reading images by file extension:
//   .hdr .pic    Radiance RGBE (picture.h), pixels converted with to_rgbe()
//   .exr         OpenEXR: R, G, B as half (default) or float, plus a float Z channel when the
//                image has depth
//   .tif .tiff   8-bit tone-mapped RGB (default) or float RGB
//   .png         8-bit tone-mapped RGB
// The 8-bit tone map, per channel: v' = clamp(exposure * v, 0, 1), then the sRGB transfer
// function (12.92 v' below 0.0031308, else 1.055 v'^(1/2.4) - 0.055), then round(255 * s).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "radcl/image/picture_header.h"
#include "radcl/image/rgbe.h"

namespace radcl::image {

struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<Color> rgb;   // width * height, top row first
  std::vector<float> depth; // empty, or width * height in the same order
};

enum class ImageKind { radiance, exr, tiff, png };
enum class ExrPixel { half, float32 };

struct ImageWriteOptions {
  ExrPixel exr_pixel = ExrPixel::half;
  bool float_tiff = false; // TIFF: linear float RGB instead of the 8-bit tone map
  double exposure = 1.0;   // multiplier before the 8-bit tone map (not applied elsewhere)
  // .hdr/.pic header lines; "#?RADIANCE" is added when empty and a FORMAT line when missing.
  PictureHeader header;
};

// The kind a file name's extension selects (case-insensitive), if any.
std::optional<ImageKind> image_kind(const std::string& path);

std::uint8_t tone_map_8bit(float v, double exposure = 1.0);

// Throws FatalError for an unknown extension, a size mismatch or a library error.
void write_image(const std::string& path, const FloatImage& img, const ImageWriteOptions& opt = {});

// Reads any of the kinds above. Radiance pictures: to_color() values, EXPOSURE not undone.
// EXR: R, G, B (and Z when present) as float. 8-bit files: code / 255, not un-tone-mapped.
FloatImage read_image(const std::string& path);

} // namespace radcl::image
