#include "radcl/image/resolution.h"

#include <cstdio>
#include <cstdlib>
#include <limits>

#include "radcl/util/error.h"

namespace radcl::image {

std::string Resolution::to_string() const {
  char buf[64];
  const char xs = x_decreasing ? '-' : '+';
  const char ys = y_decreasing ? '-' : '+';
  if (y_major)
    std::snprintf(buf, sizeof buf, "%cY %d %cX %d\n", ys, yres, xs, xres);
  else
    std::snprintf(buf, sizeof buf, "%cX %d %cY %d\n", xs, xres, ys, yres);
  return buf;
}

std::optional<Resolution> Resolution::parse(const std::string& line) {
  const auto xi = line.rfind('X');
  const auto yi = line.rfind('Y');
  if (xi == std::string::npos || yi == std::string::npos) return std::nullopt;
  Resolution r;
  r.y_major = xi > yi;
  r.x_decreasing = xi > 0 && line[xi - 1] == '-';
  r.y_decreasing = yi > 0 && line[yi - 1] == '-';
  // atoi() as Radiance, except that a count beyond int is refused instead of wrapping.
  auto count = [&line](std::size_t at) {
    const long v = std::strtol(line.c_str() + at + 1, nullptr, 10);
    return v > 0 && v <= std::numeric_limits<int>::max() ? static_cast<int>(v) : 0;
  };
  r.xres = count(xi);
  r.yres = count(yi);
  if (r.xres <= 0 || r.yres <= 0) return std::nullopt;
  return r;
}

void Resolution::to_top_down(int scan, int pos, int& col, int& row) const {
  // Image coordinates have y up (pix2loc()); a decreasing axis counts from its far end.
  const int a = y_major ? pos : scan; // along x
  const int b = y_major ? scan : pos; // along y
  col = x_decreasing ? xres - 1 - a : a;
  const int y = y_decreasing ? yres - 1 - b : b;
  row = yres - 1 - y;
}

void write_resolution(std::ostream& out, const Resolution& r) {
  const std::string s = r.to_string();
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
  if (!out) throw FatalError("write error on picture resolution");
}

Resolution read_resolution(std::istream& in, const std::string& name) {
  // Radiance reads this line with a 32-byte fgets(); allow a little more, never unbounded.
  std::string line;
  std::streambuf* sb = in.rdbuf();
  for (int c; line.size() < 64 && (c = sb->sbumpc()) != EOF && c != '\n';)
    line.push_back(static_cast<char>(c));
  const auto r = Resolution::parse(line);
  if (!r) throw FatalError("bad picture resolution string in \"" + name + "\"");
  return *r;
}

} // namespace radcl::image
