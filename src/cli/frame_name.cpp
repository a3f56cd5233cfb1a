#include "frame_name.h"

#include <cctype>
#include <cstdio>
#include <cstring>

#include "radcl/util/error.h"

namespace radcl::cli {

std::string frame_name(const std::string& pattern, int frame) {
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out += pattern[i];
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out += '%';
      ++i;
      continue;
    }
    // Flags, width and precision, then one integer conversion.
    std::size_t j = i + 1;
    while (j < pattern.size() && std::strchr("-+ #0", pattern[j]))
      ++j;
    while (j < pattern.size() &&
           (std::isdigit(static_cast<unsigned char>(pattern[j])) || pattern[j] == '.'))
      ++j;
    if (j >= pattern.size() || !std::strchr("diouxX", pattern[j]))
      throw FatalError("bad file specification \"" + pattern + "\"");
    const std::string spec = pattern.substr(i, j - i + 1);
    char buf[64];
    std::snprintf(buf, sizeof buf, spec.c_str(), frame);
    out += buf;
    i = j;
  }
  return out;
}

} // namespace radcl::cli
