// rpict -z depth files: no header, one native-endian 32-bit float distance per pixel, scanlines
// top-down as in the picture (rpict.c writes each scanline's floats with write()).
#pragma once

#include <span>
#include <string>
#include <vector>

namespace radcl::image {

class DepthWriter {
public:
  // Opens `path` for writing as rpict does: created if missing and NOT truncated, positioned
  // after `skip_scanlines` scanlines so a recovered picture continues its depth file.
  DepthWriter(const std::string& path, int width, int skip_scanlines = 0);
  ~DepthWriter();
  DepthWriter(const DepthWriter&) = delete;
  DepthWriter& operator=(const DepthWriter&) = delete;

  void write_scanline(std::span<const float> z); // z.size() == width
  void close();                                  // reports errors the destructor would hide

private:
  std::string path_;
  int fd_ = -1;
  int width_;
};

// Reads width * height floats (top-down). Throws FatalError if the file is shorter.
std::vector<float> read_depth(const std::string& path, int width, int height);

} // namespace radcl::image
