// View files (-vf): a header whose view lines are applied in order, as Radiance's viewfile().
#include "radcl/options/view.h"

#include <cctype>
#include <fstream>
#include <iostream>

namespace radcl::options {
namespace {
constexpr std::size_t kMaxLine = 2048; // Radiance's header line buffer (fgets splits longer)
}

int read_view_header(std::istream& in, View& v, std::string_view progname) {
  int first = in.peek();
  if (first == std::char_traits<char>::eof() || !std::isprint(first))
    return 0; // not a header: no view found
  int ok = 0;
  std::string line;
  while (true) {
    line.clear();
    int c;
    bool got = false;
    while (line.size() < kMaxLine - 1 && (c = in.get()) != std::char_traits<char>::eof()) {
      got = true;
      line.push_back(static_cast<char>(c));
      if (c == '\n') break;
    }
    if (!got) break;
    if (line[line[0] == '\r' ? 1 : 0] == '\n') break; // empty line ends the header
    if (is_view_line(line, progname) && scan_view_line(v, line) > 0) ++ok;
  }
  return ok;
}

int read_view_file(const std::string& name, View& v, std::string_view progname,
                   std::istream* stdin_in) {
  if (name == "-") return read_view_header(stdin_in ? *stdin_in : std::cin, v, progname);
  std::ifstream in(name, std::ios::binary);
  if (!in) return -1;
  return read_view_header(in, v, progname);
}

} // namespace radcl::options
