// A read-only streambuf over a C stdio stream (used for popen() pipes).
#pragma once

#include <cstdio>
#include <streambuf>

namespace radcl::scene::detail {

class StdioBuf : public std::streambuf {
public:
  explicit StdioBuf(std::FILE* f) : f_(f) {}

protected:
  int_type underflow() override {
    std::size_t n = std::fread(buf_, 1, sizeof buf_, f_);
    if (n == 0) return traits_type::eof();
    setg(buf_, buf_, buf_ + n);
    return traits_type::to_int_type(buf_[0]);
  }

private:
  std::FILE* f_;
  char buf_[1 << 16];
};

} // namespace radcl::scene::detail
