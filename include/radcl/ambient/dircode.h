// Radiance's 32-bit unit-vector code (../shared/docs/radiance/ambient-file.md §2), used for the
// normal and u axis of ambient records: two 13-bit magnitudes, the largest component implied, three
// sign bits.
#pragma once

#include <array>
#include <cstdint>

namespace radcl::ambient {

using Dir = std::array<double, 3>;

// encodedir(): 0 only for a vector whose components all round to 0. Components outside
// [-1, 1] are clamped (NaN counts as 0), where Radiance's conversion overflows.
std::int32_t encode_dir(const Dir& d);
// decodedir(): code 0 decodes to (0,0,0). Signs come from multiplying by -1, so a set sign bit
// on a zero component gives -0.0 (printed "-0.000000"), as Radiance's does.
Dir decode_dir(std::int32_t code);

} // namespace radcl::ambient
