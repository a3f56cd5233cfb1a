// Readers for the reference set's text files (sensor grids, rtrace outputs).
#pragma once

#include "radcl/luminance.h"
#include <array>
#include <string>
#include <vector>

namespace radcl::test {

// Rows of whitespace-separated numbers; '#' starts a comment line.
std::vector<std::vector<double>> read_table(const std::string& path);
// The same from text (a program's output): lines that do not start with a number (a header, a
// resolution string) are left out.
std::vector<std::vector<double>> parse_table(const std::string& text);
// Sensor file: 6 numbers per line (origin, direction).
std::vector<std::array<double, 6>> read_rays(const std::string& path);
// rtrace -ov output: 3 numbers per line.
std::vector<std::array<double, 3>> read_rgb(const std::string& path);

// Illuminance-style scalar of an RGB triple (Radiance's 179 lm/W luminous efficacy weights).
inline double lux(const std::array<double, 3>& c) {
  return 179.0 * radcl::bright(c);
}

} // namespace radcl::test
