// rtrace's information header and resolution line.
#include "radcl/options/ray_io.h"

#include "cformat.h"

#include <cctype>
#include <cstdint>
#include <cstring>

namespace radcl::options {
namespace {

bool space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// formatval(): "FORMAT=" followed by a non-blank value.
bool is_format_line(const std::string& s) {
  if (s.compare(0, 7, "FORMAT=") != 0) return false;
  std::size_t p = 7;
  while (p < s.size() && space(s[p]))
    ++p;
  return p < s.size();
}

// fputword(): quotes a word with whitespace, or with a quote character inside it.
std::string quote_word(const std::string& s) {
  bool has_space = false;
  char quote = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (space(s[k]))
      has_space = true;
    else if (k > 0 && s[k] == '"' && k + 1 < s.size())
      quote = '\'';
    else if (k > 0 && s[k] == '\'' && k + 1 < s.size())
      quote = '"';
  }
  if (!has_space && !quote) return s;
  if (!quote) quote = '"';
  return quote + s + quote;
}

bool host_big_endian() {
  const std::uint32_t one = 1;
  unsigned char c;
  std::memcpy(&c, &one, 1);
  return c == 0;
}

} // namespace

std::string format_command_line(const std::vector<std::string>& words) {
  std::string s;
  for (std::size_t k = 0; k < words.size(); ++k) {
    s += quote_word(words[k]);
    s += k + 1 < words.size() ? ' ' : '\n';
  }
  return s;
}

std::string format_capture_date(std::time_t t) {
  std::string s;
  std::tm tm{};
  if (localtime_r(&t, &tm))
    s += cformat("CAPDATE= %04d:%02d:%02d %02d:%02d:%02d\n", tm.tm_year + 1900, tm.tm_mon + 1,
                 tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec);
  if (gmtime_r(&t, &tm))
    s += cformat("GMT= %04d:%02d:%02d %02d:%02d:%02d\n", tm.tm_year + 1900, tm.tm_mon + 1,
                 tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec);
  return s;
}

std::string format_rtrace_header(const RtraceHeader& h) {
  std::string s;
  for (const std::string& line : h.octree_lines)
    if (!is_format_line(line)) s += line + '\n';
  s += format_command_line(h.command);
  s += "SOFTWARE= " + h.software + '\n';
  s += format_capture_date(h.time);
  if (h.ncomp > 0) s += cformat("NCOMP=%d\n", h.ncomp);
  if (h.out_format == 'f' || h.out_format == 'd')
    s += host_big_endian() ? "BigEndian=1\n" : "BigEndian=0\n";
  s += std::string("FORMAT=") + format_name(h.out_format) + '\n';
  s += '\n';
  return s;
}

std::string format_resolution(int xres, int yres) {
  return cformat("-Y %d +X %d\n", yres, xres);
}

} // namespace radcl::options
