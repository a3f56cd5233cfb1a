// `radcl`: the commands Radiance has no equivalent for. Each subcommand lives in its own
// radcl_<name>.cpp and registers itself in radcl_commands.h.
#include <cstdio>
#include <cstring>
#include <string>

#include "radcl/util/error.h"
#include "radcl_commands.h"

namespace {

void usage() {
  std::fprintf(stderr, "usage: radcl <command> [options]\n\ncommands:\n");
  for (const radcl::cli::Command& c : radcl::cli::commands())
    std::fprintf(stderr, "  %-10s %s\n", c.name, c.summary);
  std::fprintf(stderr, "  %-10s %s\n", "version", "print the version");
}

int radcl_main(int argc, char** argv) {
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
