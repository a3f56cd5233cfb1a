#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "radcl/device/embedded_sources.h"
#include "radcl/device/program.h"
#include "radcl/util/error.h"

namespace radcl::device {
namespace {

constexpr const char* kGeneratedName = "generated.cl";

// Expands `#include "name"` from the embedded sources (each file once, like #pragma once), with
// #line markers so compiler messages name the original file and line.
void expand(const std::string& name, std::string_view text, const std::string& generated,
            std::set<std::string>& seen, std::string& out) {
  if (!seen.insert(name).second) return;
  out += "#line 1 \"" + name + "\"\n";
  std::size_t line_no = 0, pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    ++line_no;
    pos = end + 1;
    std::size_t i = line.find_first_not_of(" \t");
    if (i != std::string_view::npos && line.substr(i, 8) == "#include") {
      std::size_t q1 = line.find('"', i);
      std::size_t q2 = q1 == std::string_view::npos ? q1 : line.find('"', q1 + 1);
      if (q1 == std::string_view::npos && line.find('<', i) != std::string_view::npos) {
        // <system> headers only appear in host-side branches (#ifndef __OPENCL_C_VERSION__).
        out.append(line);
        out += '\n';
        continue;
      }
      if (q2 == std::string_view::npos)
        throw FatalError("kernel source " + name + " line " + std::to_string(line_no) +
                         ": malformed #include");
      std::string inc(line.substr(q1 + 1, q2 - q1 - 1));
      if (inc == kGeneratedName)
        expand(inc, generated, generated, seen, out);
      else
        expand(inc, embedded_source(inc), generated, seen, out);
      out += "#line " + std::to_string(line_no + 1) + " \"" + name + "\"\n";
      continue;
    }
    out.append(line);
    out += '\n';
  }
}

} // namespace

std::string locate_log_lines(const std::string& log, const std::string& assembled) {
  // Original position of every assembled line, from the #line markers expand() wrote.
  std::vector<std::string> where{""};
  std::string file = "?";
  std::size_t line = 0, pos = 0;
  while (pos <= assembled.size()) {
    std::size_t end = assembled.find('\n', pos);
    if (end == std::string::npos) end = assembled.size();
    std::string_view l(assembled.data() + pos, end - pos);
    if (l.rfind("#line ", 0) == 0) {
      std::size_t q = l.find('"');
      line = std::stoul(std::string(l.substr(6))) - 1;
      if (q != std::string_view::npos) file = std::string(l.substr(q + 1, l.rfind('"') - q - 1));
      where.push_back(file + ":" + std::to_string(line));
    } else {
      where.push_back(file + ":" + std::to_string(++line));
    }
    pos = end + 1;
  }
  static const std::regex pos_re(R"(<(kernel|source)>:(\d+):)");
  std::string out;
  auto begin = std::sregex_iterator(log.begin(), log.end(), pos_re);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    std::size_t n = std::stoul((*it)[2]);
    out.append(log, last, it->position() - last);
    out += n < where.size() ? where[n] + ":" : it->str();
    last = it->position() + it->length();
  }
  out.append(log, last, std::string::npos);
  return out;
}

std::string ProgramSource::assemble() const {
  std::string out;
  std::set<std::string> seen;
  for (const std::string& root : roots)
    expand(root, embedded_source(root), generated, seen, out);
  return out;
}

} // namespace radcl::device
