#include <set>
#include <sstream>
#include <string>

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

std::string ProgramSource::assemble() const {
  std::string out;
  std::set<std::string> seen;
  for (const std::string& root : roots)
    expand(root, embedded_source(root), generated, seen, out);
  return out;
}

} // namespace radcl::device
