// The resolution string (../shared/docs/radiance/picture-format.md §3): which axis the scanlines
// follow and which way each axis runs. "-Y N +X M" is the standard top-down, left-to-right order.
#pragma once

#include <istream>
#include <optional>
#include <ostream>
#include <string>

namespace radcl::image {

struct Resolution {
  int xres = 0;
  int yres = 0;
  bool y_major = true;       // scanlines are rows ("Y" named first)
  bool x_decreasing = false; // "-X"
  bool y_decreasing = true;  // "-Y"

  static Resolution standard(int x, int y) { return {x, y, true, false, true}; }

  int scanline_length() const { return y_major ? xres : yres; }
  int num_scanlines() const { return y_major ? yres : xres; }
  bool is_standard() const { return y_major && !x_decreasing && y_decreasing; }

  // "-Y 480 +X 640\n" (resolu2str()).
  std::string to_string() const;
  // str2resolu(): the last 'X' and 'Y' in the line; the sign before, the count after each.
  static std::optional<Resolution> parse(const std::string& line);

  // Where the pixel at `pos` along file scanline `scan` lies in top-down order: its column and
  // its row counted from the top.
  void to_top_down(int scan, int pos, int& col, int& row) const;

  bool operator==(const Resolution&) const = default;
};

void write_resolution(std::ostream& out, const Resolution& r);
// Reads the line after the header. Throws FatalError naming `name` for a bad or missing line.
Resolution read_resolution(std::istream& in, const std::string& name);

} // namespace radcl::image
