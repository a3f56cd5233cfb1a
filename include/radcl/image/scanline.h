// One scanline's bytes (../shared/docs/radiance/picture-format.md §5). The encoder produces exactly
// the bytes Radiance's fwritecolrs() does; the decoder accepts everything freadcolrs() does:
// new-style RLE, flat pixels and old-style repeat markers, detected per scanline.
#pragma once

#include <span>
#include <streambuf>
#include <vector>

#include "radcl/image/rgbe.h"

namespace radcl::image {

// New-style RLE needs 8 <= length <= 0x7fff; other lengths are written flat.
constexpr int kMinRleLength = 8;
constexpr int kMaxRleLength = 0x7fff;

// Appends the encoded scanline to `out`.
void encode_scanline(std::span<const Rgbe> pixels, std::vector<unsigned char>& out);

enum class ScanStatus {
  ok,
  truncated, // the data ended inside the scanline (or before it)
  corrupt,   // an RLE length mismatch, a packet past the end, a repeat with nothing before it
};

// Decodes one scanline of pixels.size() pixels from `in`.
ScanStatus decode_scanline(std::streambuf& in, std::span<Rgbe> pixels);

} // namespace radcl::image
