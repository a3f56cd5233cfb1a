// rtrace's and rpict's whole command line as a user gives it: argv words, option files, their
// nesting, environment words and a view file. The input is NUL-separated: the argv words, then
// the contents of option files a and b, the values of variables A and B, and a view file v.
// The words "@a", "@b", "$A", "$B" and "v" name those (written to a scratch folder for each
// input, the variables set in the environment); other words that would reach the machine's
// files ('/', '@', '$') are skipped, as in fuzz_options. rpict's -vf - reads the view file's
// text from standard input.
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "fuzz_target.h"
#include "radcl/options/rpict_options.h"
#include "radcl/options/rtrace_options.h"

namespace {

std::filesystem::path scratch() {
  static const std::filesystem::path dir = [] {
    auto p =
        std::filesystem::temp_directory_path() / ("radcl-fuzz-cmd-" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return dir;
}

// The words of `text` with the names of the scratch files and variables made real; false if a
// word would reach anything else of the machine.
bool rewrite(const std::string& text, std::vector<std::string>& out) {
  const std::string dir = scratch().string();
  for (const std::string& w : radcl::options::split_words(text)) {
    if (w == "@a" || w == "@b")
      out.push_back("@" + dir + "/" + w.substr(1));
    else if (w == "$A" || w == "$B")
      out.push_back("$RADCL_FUZZ_" + w.substr(1));
    else if (w == "v")
      out.push_back(dir + "/v");
    else if (w[0] == '@' || w[0] == '$' || w.find('/') != std::string::npos)
      return false;
    else
      out.push_back(w);
  }
  return true;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words)
    s += w + "\n";
  return s;
}

} // namespace

RADCL_FUZZ_TARGET(command_line) {
  using namespace radcl::options;
  std::array<std::string, 6> part;
  std::size_t k = 0, at = 0;
  for (; k < part.size() - 1; ++k) {
    const std::size_t nul = data.find('\0', at);
    if (nul == std::string_view::npos) break;
    part[k] = std::string(data.substr(at, nul - at));
    at = nul + 1;
  }
  part[k] = std::string(data.substr(std::min(at, data.size())));
  std::array<std::vector<std::string>, 5> words;
  for (std::size_t i = 0; i < words.size(); ++i)
    if (!rewrite(part[i], words[i])) return;
  const std::filesystem::path dir = scratch();
  std::ofstream(dir / "a", std::ios::binary) << joined(words[1]);
  std::ofstream(dir / "b", std::ios::binary) << joined(words[2]);
  std::ofstream(dir / "v", std::ios::binary) << part[5];
  ::setenv("RADCL_FUZZ_A", joined(words[3]).c_str(), 1);
  ::setenv("RADCL_FUZZ_B", joined(words[4]).c_str(), 1);
  std::vector<std::string> argv{"rtrace"};
  argv.insert(argv.end(), words[0].begin(), words[0].end());
  const FileFinder none = [](const std::string&) { return std::string(); };
  try {
    const RtraceCommand c = parse_rtrace_command_line(argv, none);
    (void)format_rtrace_defaults(c.opt);
  } catch (const radcl::FatalError&) {
  }
  argv[0] = "rpict";
  std::istringstream in(part[5]);
  const RpictCommand c = parse_rpict_command_line(argv, none, &in);
  (void)format_rpict_defaults(c.opt);
}
