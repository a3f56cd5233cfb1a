#include "radcl/sky/program.h"

#include <cctype>
#include <cstdarg>
#include <cstdio>

namespace radcl::sky {

void appendf(std::string& s, const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  const int n = std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  if (n < 0) return;
  if (static_cast<std::size_t>(n) < sizeof buf) {
    s.append(buf, n);
    return;
  }
  std::string big(n + 1, '\0');
  va_start(ap, fmt);
  std::vsnprintf(big.data(), big.size(), fmt, ap);
  va_end(ap);
  s.append(big.data(), n);
}

namespace {
std::string quoted_word(const std::string& w) {
  bool space = false;
  char quote = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const bool inner = i > 0 && i + 1 < w.size();
    if (std::isspace(static_cast<unsigned char>(w[i])))
      space = true;
    else if (inner && w[i] == '"')
      quote = '\'';
    else if (inner && w[i] == '\'')
      quote = '"';
  }
  if (!space && !quote) return w;
  if (!quote) quote = '"';
  return quote + w + quote;
}
} // namespace

std::string format_command_line(const std::vector<std::string>& argv) {
  std::string s;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    s += quoted_word(argv[i]);
    s += i + 1 < argv.size() ? ' ' : '\n';
  }
  return s;
}

} // namespace radcl::sky
