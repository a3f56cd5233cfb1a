// printf into a std::string: Radiance's outputs are defined by C format strings, so radcl
// uses the same ones rather than re-deriving them with iostreams.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace radcl::options {

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
inline std::string
cformat(const char* fmt, ...) {
  char buf[256];
  va_list ap;
  va_start(ap, fmt);
  int n = std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  if (n < 0) return {};
  if (static_cast<std::size_t>(n) < sizeof buf)
    return std::string(buf, static_cast<std::size_t>(n));
  std::string s(static_cast<std::size_t>(n) + 1, '\0');
  va_start(ap, fmt);
  std::vsnprintf(s.data(), s.size(), fmt, ap);
  va_end(ap);
  s.resize(static_cast<std::size_t>(n));
  return s;
}

} // namespace radcl::options
