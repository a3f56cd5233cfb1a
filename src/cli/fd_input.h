// Standard input as a std::istream that can tell whether more bytes are ready without
// blocking, so rtrace can answer the rays it has before waiting for more (co-process use).
#pragma once

#include <istream>
#include <streambuf>
#include <vector>

namespace radcl::cli {

class FdInputBuf : public std::streambuf {
public:
  explicit FdInputBuf(int fd, std::size_t size = 1 << 16);
  // True when reading the next record cannot block: the buffer holds `record` bytes (binary
  // input), or some non-blank text (ascii input, record = 0), or the descriptor has input or
  // EOF pending right now.
  bool ready(std::size_t record = 0);

protected:
  int_type underflow() override;

private:
  int fd_;
  std::vector<char> buf_;
};

} // namespace radcl::cli
