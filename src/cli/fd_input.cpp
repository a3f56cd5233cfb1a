#include "fd_input.h"

#include <cctype>
#include <cerrno>
#include <poll.h>
#include <unistd.h>

namespace radcl::cli {

FdInputBuf::FdInputBuf(int fd, std::size_t size) : fd_(fd), buf_(size) {
  setg(buf_.data(), buf_.data(), buf_.data());
}

bool FdInputBuf::ready(std::size_t record) {
  if (record > 0) {
    if (static_cast<std::size_t>(egptr() - gptr()) >= record) return true;
  } else {
    for (const char* c = gptr(); c < egptr(); ++c)
      if (!std::isspace(static_cast<unsigned char>(*c))) return true;
  }
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

FdInputBuf::int_type FdInputBuf::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  ssize_t n;
  do {
    n = ::read(fd_, buf_.data(), buf_.size());
  } while (n < 0 && errno == EINTR);
  if (n <= 0) return traits_type::eof();
  setg(buf_.data(), buf_.data(), buf_.data() + n);
  return traits_type::to_int_type(*gptr());
}

} // namespace radcl::cli
