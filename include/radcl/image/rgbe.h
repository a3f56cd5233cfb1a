// Radiance's 4-byte pixels (../shared/docs/radiance/picture-format.md §4): three mantissas sharing
// one exponent, excess 128. The conversions reproduce Radiance's setcolr()/colr_color() to the bit,
// so pictures we write decode to the same values Radiance's tools see.
#pragma once

#include <array>
#include <cstdint>

namespace radcl::image {

// R (or X), G (Y), B (Z), E: the byte order in files.
using Rgbe = std::array<std::uint8_t, 4>;
using Color = std::array<float, 3>;

// setcolr(): truncating conversion; negatives clamp to 0, maxima <= 1e-32 give (0,0,0,0).
// Where setcolr() is undefined: a NaN maximum gives (0,0,0,0), an infinite one 255 for each
// +inf channel, 0 for the others, exponent 255.
Rgbe to_rgbe(double r, double g, double b);
inline Rgbe to_rgbe(const Color& c) {
  return to_rgbe(c[0], c[1], c[2]);
}

// colr_color(): the centre of the code's interval, (m + 0.5) * 2^(E-136); E = 0 is black.
Color to_color(const Rgbe& p);

} // namespace radcl::image
