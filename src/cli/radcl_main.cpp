// `radcl`: the commands Radiance has no equivalent for. Each subcommand lives in its own
// radcl_<name>.cpp and registers itself in radcl_commands.h.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "radcl/options/args.h"
#include "radcl/util/error.h"
#include "radcl_commands.h"

namespace {

void usage() {
  std::fprintf(stderr, "usage: radcl <command> [options]\n\ncommands:\n");
  for (const radcl::cli::Command& c : radcl::cli::commands())
    std::fprintf(stderr, "  %-10s %s\n", c.name, c.summary);
  std::fprintf(stderr, "  %-10s %s\n", "version", "print the version");
}

int radcl_main(int argc0, char** argv0) {
  // Option files and variables expand as in rtrace and rpict (options/args.h), anywhere.
  radcl::options::ArgList args(argc0, argv0);
  for (std::size_t i = 1; i < args.size(); ++i)
    args.expand(i);
  std::vector<std::string> words = args.words();
  std::vector<char*> ptrs;
  for (std::string& w : words)
    ptrs.push_back(w.data());
  ptrs.push_back(nullptr);
  const int argc = static_cast<int>(words.size());
  char** argv = ptrs.data();
  if (argc < 2) {
    usage();
    return 1;
  }
  std::string cmd = argv[1];
  if (cmd == "version" || cmd == "-version" || cmd == "--version") {
    std::printf("radcl %s\n", RADCL_VERSION);
    return 0;
  }
  if (cmd == "help" || cmd == "-h" || cmd == "--help") {
    usage();
    return 0;
  }
  for (const radcl::cli::Command& c : radcl::cli::commands())
    if (cmd == c.name) return c.run(argc - 1, argv + 1);
  throw radcl::FatalError("unknown command \"" + cmd + "\" (try radcl help)");
}

} // namespace

int main(int argc, char** argv) {
  return radcl::run_main("radcl", radcl_main, argc, argv);
}
