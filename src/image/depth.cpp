#include "radcl/image/depth.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <unistd.h>

#include "radcl/util/error.h"

namespace radcl::image {

DepthWriter::DepthWriter(const std::string& path, int width, int skip_scanlines)
    : path_(path), width_(width) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT, 0666);
  if (fd_ < 0) throw FatalError("cannot open z-file \"" + path + "\"");
  const off_t at = static_cast<off_t>(skip_scanlines) * width * sizeof(float);
  if (at > 0 && ::lseek(fd_, at, SEEK_SET) < 0) {
    ::close(fd_);
    fd_ = -1;
    throw FatalError("z-file seek error on \"" + path + "\"");
  }
}

DepthWriter::~DepthWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void DepthWriter::write_scanline(std::span<const float> z) {
  if (static_cast<int>(z.size()) != width_)
    throw FatalError("internal error: depth scanline length mismatch");
  const char* p = reinterpret_cast<const char*>(z.data());
  std::size_t left = z.size_bytes();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw FatalError("write error on z-file \"" + path_ + "\": " + std::strerror(errno));
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void DepthWriter::close() {
  if (fd_ < 0) return;
  const int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0) throw FatalError("error closing z-file \"" + path_ + "\"");
}

std::vector<float> read_depth(const std::string& path, int width, int height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FatalError("cannot open z-file \"" + path + "\"");
  std::vector<float> z(static_cast<std::size_t>(width) * height);
  in.read(reinterpret_cast<char*>(z.data()),
          static_cast<std::streamsize>(z.size() * sizeof(float)));
  if (in.gcount() != static_cast<std::streamsize>(z.size() * sizeof(float)))
    throw FatalError("z-file \"" + path + "\" is shorter than " + std::to_string(width) + "x" +
                     std::to_string(height) + " floats");
  return z;
}

} // namespace radcl::image
