// rtrace's and rpict's command-line parsers. The input up to the first NUL is split into
// words (argv after argv[0]); what follows the NUL is standard input for `-vf -`.
// Inputs that would make the parsers read the machine's files or environment ("@file",
// "$VAR", any word with '/') are skipped: their results would depend on the machine, and
// "@/dev/stdin" would block. Auxiliary name files (-aI, -tE, ...) are never found.
#include <sstream>

#include "fuzz_target.h"
#include "radcl/options/rpict_options.h"
#include "radcl/options/rtrace_options.h"

RADCL_FUZZ_TARGET(options) {
  using namespace radcl::options;
  const std::size_t nul = data.find('\0');
  const std::vector<std::string> words = split_words(data.substr(0, nul));
  for (const std::string& w : words)
    if (w[0] == '@' || w[0] == '$' || w.find('/') != std::string::npos) return;
  const FileFinder none = [](const std::string&) { return std::string(); };
  const std::string stdin_text(nul == std::string_view::npos ? "" : data.substr(nul + 1));

  std::vector<std::string> argv{"rtrace"};
  argv.insert(argv.end(), words.begin(), words.end());
  try {
    const RtraceCommand c = parse_rtrace_command_line(argv, none);
    (void)format_rtrace_defaults(c.opt);
    (void)rtrace_octree(c);
  } catch (const radcl::FatalError&) {
  }

  argv[0] = "rpict";
  std::istringstream in(stdin_text);
  const RpictCommand c = parse_rpict_command_line(argv, none, &in);
  (void)format_rpict_defaults(c.opt);
  (void)rpict_octree(c);
}
